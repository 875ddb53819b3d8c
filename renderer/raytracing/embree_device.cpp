#include "renderer/raytracing/embree_device.h"

#include <stdexcept>
#include <utility>

namespace ml {

namespace {

const char* errorName(RTCError code) {
    switch (code) {
        case RTC_ERROR_NONE: return "no error";
        case RTC_ERROR_UNKNOWN: return "unknown error";
        case RTC_ERROR_INVALID_ARGUMENT: return "invalid argument";
        case RTC_ERROR_INVALID_OPERATION: return "invalid operation";
        case RTC_ERROR_OUT_OF_MEMORY: return "out of memory";
        case RTC_ERROR_UNSUPPORTED_CPU: return "unsupported CPU";
        case RTC_ERROR_CANCELLED: return "cancelled";
    }
    return "error";
}

}  // namespace

EmbreeDevice::EmbreeDevice(std::string subject) : subject_(std::move(subject)) {
    device_ = rtcNewDevice(nullptr);
    if (device_ == nullptr)
        throw std::runtime_error(subject_ + ": Embree could not make a device: " + errorName(rtcGetDeviceError(nullptr)));
    rtcSetDeviceErrorFunction(device_, &EmbreeDevice::onError, this);
}

EmbreeDevice::~EmbreeDevice() {
    if (device_ != nullptr) rtcReleaseDevice(device_);
}

void EmbreeDevice::onError(void* self, RTCError code, const char* message) {
    auto* device = static_cast<EmbreeDevice*>(self);
    const std::lock_guard<std::mutex> lock(device->mutex_);
    if (device->error_.empty()) device->error_ = std::string(errorName(code)) + (message != nullptr ? std::string(": ") + message : "");
}

void EmbreeDevice::check(const char* doing) const {
    const RTCError code = rtcGetDeviceError(device_);
    const std::lock_guard<std::mutex> lock(mutex_);
    if (error_.empty() && code == RTC_ERROR_NONE) return;
    throw std::runtime_error(subject_ + ": Embree failed to " + doing + ": " + (error_.empty() ? errorName(code) : error_));
}

}  // namespace ml
