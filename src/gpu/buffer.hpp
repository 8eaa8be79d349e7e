#pragma once
// A uniform buffer (std140 data shared by a pass, e.g. the live drops). Made by Device::create_buffer.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>

#include "gpu/handle.hpp"

namespace puddle::gpu {

struct BufferDesc {
    std::string label;
    std::size_t size = 0;  // bytes, fixed for the buffer's life
};

namespace detail {
void delete_buffer(std::uint32_t id);
}

class Buffer {
public:
    Buffer() = default;
    std::uint32_t id() const { return id_.get(); }  // the GL buffer name
    std::size_t size() const { return size_; }
    // Replaces bytes [offset, offset + data.size()); never reallocates.
    void write(std::span<const std::byte> data, std::size_t offset = 0);

private:
    friend class Device;
    GlHandle<detail::delete_buffer> id_;
    std::size_t size_ = 0;
};

}  // namespace puddle::gpu
