// Whether the current GL context offers an extension (glGetStringi over GL_EXTENSIONS).
#pragma once

namespace ml::gl {

bool hasExtension(const char* name);

}  // namespace ml::gl
