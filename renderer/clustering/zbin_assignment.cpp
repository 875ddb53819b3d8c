#include "renderer/clustering/zbin_assignment.h"

#include <stdexcept>
#include <string>

#include "glsl/include/bindings.h"
#include "renderer/lights/light_buffers.h"

namespace ml {

namespace {

constexpr GLbitfield kComputeToCompute = GL_SHADER_STORAGE_BARRIER_BIT | GL_BUFFER_UPDATE_BARRIER_BIT;

gl::Program zbinProgram(const char* label, const char* phase, bool spotLights, shaders::Defines defines = {}) {
    defines.insert(defines.begin(), {{phase, "1"}, spotLightsDefine(spotLights)});
    return gl::Program(label, {{GL_COMPUTE_SHADER, "zbin_assign.comp"}}, defines);
}

// Runs a pass over groupsX x groupsY workgroups (none when there is nothing to do) and makes
// its writes visible to the next.
void runPass(const gl::Program& program, GLuint groupsX, GLuint groupsY = 1) {
    program.use();
    if (groupsX > 0 && groupsY > 0) glDispatchCompute(groupsX, groupsY, 1);
    glMemoryBarrier(kComputeToCompute);
}

std::string mib(std::size_t bytes) { return std::to_string((bytes + (1u << 20) - 1) >> 20) + " MiB"; }

}  // namespace

ZBinAssignment::ZBinAssignment(bool spotLights, const std::pair<std::string, std::string>& depthSamples)
    : keysPass_(zbinProgram("zbin.keys", "ML_ZBIN_KEYS", spotLights)),
      binsPass_(zbinProgram("zbin.bins", "ML_ZBIN_BINS", spotLights)),
      masksPass_(zbinProgram("zbin.tile-masks", "ML_ZBIN_TILE_MASKS", spotLights)),
      statsPass_(zbinProgram("zbin.stats", "ML_ZBIN_STATS", spotLights, {depthSamples})),
      params_("zbin.params", 16) {}

void ZBinAssignment::build(const FrameContext& ctx, const ClusterGrid& grid, std::size_t maxStorageBlock) {
    grid_ = grid;
    lights_ = ctx.lights.count();
    depth_ = ctx.targets.opaqueDepth().id();
    width_ = ctx.targets.width();
    height_ = ctx.targets.height();
    const std::uint32_t tiles = grid.tilesX * grid.tilesY;
    const std::uint32_t bins = grid.slices * ML_ZBIN_PER_SLICE;
    keys_.ensure(std::size_t(lights_) * 4);
    sortedLights_.ensure(std::size_t(lights_) * 4);
    lightView_.ensure(std::size_t(lights_) * 16);
    sortedView_.ensure(std::size_t(lights_) * 16);
    ranges_.ensure(std::size_t(bins) * 8);

    ctx.lights.bindForReading();
    params_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_ZBIN_PARAMS);
    lightView_.buffer().bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_LIGHT_VIEW);
    {
        auto pass = ctx.timer.pass("zbin.keys");
        glClearNamedBufferData(params_.id(), GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, nullptr);
        glMemoryBarrier(kComputeToCompute);
        keys_.buffer().bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_RADIX_KEYS_IN);
        sortedLights_.buffer().bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_ZBIN_SORTED_LIGHTS);
        runPass(keysPass_, gl::groupsFor(lights_, ML_ZBIN_WORKGROUP));
    }
    {
        auto pass = ctx.timer.pass("zbin.sort");
        sort_.sort(keys_.buffer(), sortedLights_.buffer(), lights_);
    }
    // The masks are sized by the lights that survived culling (one 16-byte read per frame).
    glm::uvec4 params{};
    params_.download(&params, sizeof(params));
    listed_ = params.y;
    words_ = (listed_ + 31) / 32;
    const std::size_t maskBytes = std::size_t(tiles) * words_ * 4;
    if (maskBytes > maxStorageBlock)
        throw std::runtime_error("--assign zbin: the tile masks need " + mib(maskBytes) + " (" + std::to_string(tiles) +
                                 " tiles x " + std::to_string(words_) + " words of 32 lights x 4 B), more than this GPU's "
                                 "GL_MAX_SHADER_STORAGE_BLOCK_SIZE (" + mib(maxStorageBlock) +
                                 "); lower --tiles-x or --lights, or use --assign exact");
    GLint maxGroupsY = 0;
    glGetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_COUNT, 1, &maxGroupsY);
    if (tiles > static_cast<std::uint32_t>(maxGroupsY))
        throw std::runtime_error("--assign zbin: " + std::to_string(tiles) + " tiles, more than this GPU dispatches (" +
                                 std::to_string(maxGroupsY) + "); lower --tiles-x");
    params.x = words_;
    params_.upload(&params, sizeof(params));
    {
        auto pass = ctx.timer.pass("zbin.bins");
        const glm::uvec2 empty(~0u, 0u);
        glClearNamedBufferSubData(ranges_.buffer().id(), GL_RG32UI, 0, static_cast<GLsizeiptr>(std::size_t(bins) * 8),
                                  GL_RG_INTEGER, GL_UNSIGNED_INT, &empty);
        glMemoryBarrier(kComputeToCompute);
        params_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_ZBIN_PARAMS);
        ranges_.buffer().bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_ZBIN_RANGES);
        sortedLights_.buffer().bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_ZBIN_SORTED_LIGHTS);
        lightView_.buffer().bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_LIGHT_VIEW);
        sortedView_.buffer().bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_ZBIN_SORTED_VIEW);
        runPass(binsPass_, gl::groupsFor(listed_, ML_ZBIN_WORKGROUP));
    }
    {
        auto pass = ctx.timer.pass("zbin.tile-masks");
        masks_.ensure(maskBytes);
        masks_.buffer().bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_ZBIN_TILE_MASKS);
        runPass(masksPass_, gl::groupsFor(words_, ML_ZBIN_WORKGROUP), tiles);
    }
}

void ZBinAssignment::bindForShading() const {
    params_.bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_ZBIN_PARAMS);
    ranges_.buffer().bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_ZBIN_RANGES);
    masks_.buffer().bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_ZBIN_TILE_MASKS);
    sortedLights_.buffer().bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_ZBIN_SORTED_LIGHTS);
}

ZBinStatistics ZBinAssignment::statistics() const {
    ZBinStatistics s;
    s.tiles = grid_.tilesX * grid_.tilesY;
    s.bins = grid_.slices * ML_ZBIN_PER_SLICE;
    s.wordsPerTile = words_;
    s.listedLights = listed_;
    s.maskBytes = std::size_t(s.tiles) * words_ * 4;
    s.totalBytes = s.maskBytes + std::size_t(s.bins) * 8 + 16 + std::size_t(lights_) * (4 + 4 + 16 + 16) +
                   RadixSort::scratchBytes(lights_);
    if (width_ <= 0 || height_ <= 0) return s;

    const GLuint groupsX = gl::groupsFor(width_, ML_SCREEN_TILE), groupsY = gl::groupsFor(height_, ML_SCREEN_TILE);
    groupStats_.ensure(std::size_t(groupsX) * groupsY * 16);
    bindForShading();
    groupStats_.buffer().bindBase(GL_SHADER_STORAGE_BUFFER, ML_SSBO_ZBIN_STATS);
    glBindTextureUnit(ML_TEX_DEPTH, depth_);
    statsPass_.use();
    glDispatchCompute(groupsX, groupsY, 1);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    std::vector<glm::uvec4> groups(std::size_t(groupsX) * groupsY);
    groupStats_.buffer().download(groups.data(), groups.size() * sizeof(glm::uvec4));
    std::uint64_t pixels = 0, walked = 0, passed = 0;
    for (const glm::uvec4& g : groups) {
        pixels += g.x;
        walked += g.y;
        passed += g.z;
    }
    if (pixels > 0) {
        s.meanWalkedPerPixel = double(walked) / double(pixels);
        s.meanPassedPerPixel = double(passed) / double(pixels);
    }
    return s;
}

std::vector<std::uint32_t> ZBinAssignment::downloadSortedLights() const {
    std::vector<std::uint32_t> sorted(listed_);
    sortedLights_.buffer().download(sorted.data(), sorted.size() * 4);
    return sorted;
}

std::vector<glm::uvec2> ZBinAssignment::downloadBinRanges() const {
    std::vector<glm::uvec2> ranges(std::size_t(grid_.slices) * ML_ZBIN_PER_SLICE);
    ranges_.buffer().download(ranges.data(), ranges.size() * sizeof(glm::uvec2));
    return ranges;
}

std::vector<std::uint32_t> ZBinAssignment::downloadTileMasks() const {
    std::vector<std::uint32_t> masks(std::size_t(grid_.tilesX) * grid_.tilesY * words_);
    masks_.buffer().download(masks.data(), masks.size() * 4);
    return masks;
}

}  // namespace ml
