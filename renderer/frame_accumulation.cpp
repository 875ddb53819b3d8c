#include "renderer/frame_accumulation.h"

namespace ml {

FloatImage renderAccumulated(FrameRenderer& renderer, std::uint32_t frameIndex, std::uint32_t draws) {
    FloatImage mean;
    std::vector<double> sum;  // double: a thousand draws keep their last bits
    for (std::uint32_t k = 0; k < draws; ++k) {
        renderer.render(frameIndex, k);
        const FloatImage hdr = renderer.readHdr();
        if (sum.empty()) {
            mean = FloatImage{hdr.width, hdr.height, {}};
            sum.assign(hdr.pixels.size(), 0.0);
        }
        for (std::size_t i = 0; i < sum.size(); ++i) sum[i] += hdr.pixels[i];
    }
    mean.pixels.resize(sum.size());
    for (std::size_t i = 0; i < sum.size(); ++i) mean.pixels[i] = static_cast<float>(sum[i] / draws);
    return mean;
}

}  // namespace ml
