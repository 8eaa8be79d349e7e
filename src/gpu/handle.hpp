#pragma once
// A move-only owner of one GL object name; Delete is called with the name when it dies. The name is a
// plain std::uint32_t (what GLuint is; gpu/gl.hpp checks), so this header and every public gpu header
// that holds a handle stay free of GL's headers.

#include <cstdint>
#include <utility>

namespace puddle::gpu {

template <void (*Delete)(std::uint32_t)>
class GlHandle {
public:
    GlHandle() = default;
    explicit GlHandle(std::uint32_t id) : id_(id) {}
    GlHandle(GlHandle&& o) noexcept : id_(std::exchange(o.id_, 0)) {}
    GlHandle& operator=(GlHandle&& o) noexcept {
        if (this != &o) {
            reset();
            id_ = std::exchange(o.id_, 0);
        }
        return *this;
    }
    GlHandle(const GlHandle&) = delete;
    GlHandle& operator=(const GlHandle&) = delete;
    ~GlHandle() { reset(); }
    // The GL object name (0: none).
    std::uint32_t get() const { return id_; }
    std::uint32_t release() { return std::exchange(id_, 0); }
    void reset() {
        if (id_) Delete(std::exchange(id_, 0));
    }
    explicit operator bool() const { return id_ != 0; }

private:
    std::uint32_t id_ = 0;
};

}  // namespace puddle::gpu
