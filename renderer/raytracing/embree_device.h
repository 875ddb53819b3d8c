// An Embree device (libembree-dev, Embree 3) that keeps the first error Embree reports, so that
// the shadow BVH's build and the tests' Embree oracle fail in one line naming what they worked on.
// Only .cpp files include this header: Embree's headers stay out of the rest of the renderer.
#pragma once

#include <mutex>
#include <string>

#include <embree3/rtcore.h>

namespace ml {

class EmbreeDevice {
public:
    // `subject` starts every message, e.g. "scene sponza". Throws std::runtime_error where Embree
    // cannot make a device (no supported CPU, a bad configuration).
    explicit EmbreeDevice(std::string subject);
    ~EmbreeDevice();
    EmbreeDevice(const EmbreeDevice&) = delete;
    EmbreeDevice& operator=(const EmbreeDevice&) = delete;

    RTCDevice get() const { return device_; }
    // Throws std::runtime_error("<subject>: Embree failed to <doing>: <code>: <message>") if
    // Embree reported an error since the device was made.
    void check(const char* doing) const;

private:
    static void onError(void* self, RTCError code, const char* message);

    RTCDevice device_ = nullptr;
    std::string subject_;
    mutable std::mutex mutex_;  // Embree reports from its build threads
    std::string error_;  // the first one: later ones usually follow from it
};

}  // namespace ml
