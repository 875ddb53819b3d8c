// Clustered forward (Forward+): a depth pre-pass, light assignment into clusters, then the
// scene is rastered again and each fragment loops over its cluster's lights only.
#pragma once

#include "renderer/clustering/clustered_lighting.h"
#include "renderer/gl/program.h"
#include "renderer/methods/shading_method.h"

namespace ml {

class ForwardPlus final : public ShadingMethod {
public:
    explicit ForwardPlus(const ClusteringSettings& settings);
    std::string name() const override { return "forward-plus"; }
    void render(const FrameContext& ctx) override;
    const ClusteredLighting* clustering() const override { return &clustering_; }

private:
    gl::Program depthProgram_;
    gl::Program shadeProgram_;
    ClusteredLighting clustering_;
};

}  // namespace ml
