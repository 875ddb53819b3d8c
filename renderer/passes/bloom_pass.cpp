#include "renderer/passes/bloom_pass.h"

#include <cmath>

namespace ml {

namespace {
// In half-resolution pixels: the kernel reaches 8 (16 full-resolution pixels) each side,
// where the weight has fallen to exp(-64 / 18), 3 % of the centre's.
constexpr float kBloomSigma = 3.0f;
constexpr GLbitfield kImageToImage = GL_SHADER_IMAGE_ACCESS_BARRIER_BIT;
}  // namespace

std::array<float, ML_BLOOM_RADIUS + 1> bloomKernel() {
    std::array<float, ML_BLOOM_RADIUS + 1> w{};
    float sum = 0.0f;
    for (int i = 0; i <= ML_BLOOM_RADIUS; ++i) {
        w[i] = std::exp(-static_cast<float>(i * i) / (2.0f * kBloomSigma * kBloomSigma));
        sum += i == 0 ? w[i] : 2.0f * w[i];
    }
    for (float& v : w) v /= sum;
    return w;
}

// The programs are built on first use: most frames never bloom.
BloomPass::BloomPass() = default;

void BloomPass::prepare(int width, int height) {
    if (!bright_) {
        bright_ = gl::Program::compute("bloom_bright.comp");
        blur_ = gl::Program::compute("bloom_blur.comp");
        composite_ = gl::Program::compute("bloom_composite.comp");
        const auto weights = bloomKernel();
        glProgramUniform1fv(blur_.id(), glGetUniformLocation(blur_.id(), "u_weights"), static_cast<GLsizei>(weights.size()),
                            weights.data());
    }
    if (width == width_ && height == height_) return;
    width_ = width;
    height_ = height;
    const int halfW = (width + 1) / 2, halfH = (height + 1) / 2;
    half_[0] = gl::Texture2D("bloom.half-a", GL_RGBA32F, halfW, halfH);
    half_[1] = gl::Texture2D("bloom.half-b", GL_RGBA32F, halfW, halfH);
}

std::size_t BloomPass::bytes() const {
    return half_[0] ? 2 * static_cast<std::size_t>(half_[0].width()) * half_[0].height() * 16 : 0;
}

void BloomPass::run(const FrameTargets& targets, const BloomSettings& settings, PassTimer& timer) {
    if (!settings.enabled) return;
    prepare(targets.outputWidth(), targets.outputHeight());
    const GLuint halfX = gl::groupsFor(half_[0].width(), ML_BLOOM_TILE), halfY = gl::groupsFor(half_[0].height(), ML_BLOOM_TILE);
    {
        auto pass = timer.pass("bloom.bright-pass");
        bright_.use();
        bright_.set("u_threshold", settings.threshold);
        glBindImageTexture(ML_IMG_HDR, targets.outputHdr().id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
        glBindImageTexture(ML_IMG_BLOOM_OUT, half_[0].id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
        glDispatchCompute(halfX, halfY, 1);
        glMemoryBarrier(kImageToImage);
    }
    blur_.use();
    const char* names[2] = {"bloom.blur-h", "bloom.blur-v"};
    for (int step = 0; step < 2; ++step) {
        auto pass = timer.pass(names[step]);
        // Across from a to b, then down from b back to a.
        blur_.set("u_vertical", static_cast<unsigned>(step));
        glBindImageTexture(ML_IMG_BLOOM_IN, half_[step].id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
        glBindImageTexture(ML_IMG_BLOOM_OUT, half_[1 - step].id(), 0, GL_FALSE, 0, GL_WRITE_ONLY, GL_RGBA32F);
        glDispatchCompute(halfX, halfY, 1);
        glMemoryBarrier(kImageToImage);
    }
    {
        auto pass = timer.pass("bloom.composite");
        composite_.use();
        composite_.set("u_strength", settings.strength);
        glBindImageTexture(ML_IMG_HDR, targets.outputHdr().id(), 0, GL_FALSE, 0, GL_READ_WRITE, GL_RGBA32F);
        glBindImageTexture(ML_IMG_BLOOM_IN, half_[0].id(), 0, GL_FALSE, 0, GL_READ_ONLY, GL_RGBA32F);
        glDispatchCompute(gl::groupsFor(targets.outputWidth(), ML_BLOOM_TILE), gl::groupsFor(targets.outputHeight(), ML_BLOOM_TILE), 1);
        glMemoryBarrier(kImageToImage | GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT);
    }
}

}  // namespace ml
