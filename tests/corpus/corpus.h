// What the corpus tests share: where the corpus is (ML_CORPUS_DIR, ../shared/corpus beside the
// checkout) and the methods they render.
#pragma once

#include <filesystem>
#include <string>

#include "renderer/methods/shading_method.h"

namespace ml::test {

inline std::string corpusPath(const std::string& relative) { return (std::filesystem::path(ML_CORPUS_DIR) / relative).string(); }

// Naive first: the reference the others are held to.
inline constexpr MethodKind kEveryMethod[] = {MethodKind::Naive, MethodKind::ForwardPlus, MethodKind::Deferred,
                                              MethodKind::Visibility};

}  // namespace ml::test
