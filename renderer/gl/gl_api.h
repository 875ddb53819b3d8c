// The one place the GL loader is included from, so every file sees the same declarations.
#pragma once

#include <glad/gl.h>
