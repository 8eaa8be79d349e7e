#pragma once
// A move-only owner of one GL object name; Deleter is called with the name when it dies.

#include <utility>

#include "gpu/gl.hpp"

namespace puddle::gpu {

template <void (*Delete)(GLuint)>
class GlHandle {
public:
    GlHandle() = default;
    explicit GlHandle(GLuint id) : id_(id) {}
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
    GLuint get() const { return id_; }
    GLuint release() { return std::exchange(id_, 0); }
    void reset() {
        if (id_) Delete(std::exchange(id_, 0));
    }
    explicit operator bool() const { return id_ != 0; }

private:
    GLuint id_ = 0;
};

}  // namespace puddle::gpu
