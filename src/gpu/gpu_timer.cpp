#include "gpu/gpu_timer.hpp"

#include <cstddef>

#include "gpu/device.hpp"
#include "gpu/gl.hpp"

// GL_EXT_disjoint_timer_query's names; on GLES 3 its queries go through the core glBeginQuery family.
#ifndef GL_TIME_ELAPSED_EXT
#define GL_TIME_ELAPSED_EXT 0x88BF
#endif
#ifndef GL_GPU_DISJOINT_EXT
#define GL_GPU_DISJOINT_EXT 0x8FBB
#endif

namespace puddle::gpu {

namespace detail {
void delete_query(std::uint32_t id) {
    glDeleteQueries(1, &id);
}
}  // namespace detail

GpuTimer Device::create_gpu_timer() {
    GpuTimer timer;
    if (!caps_.timer_queries) return timer;
    for (auto& query : timer.queries_) {
        GLuint id = 0;
        glGenQueries(1, &id);
        query = GlHandle<detail::delete_query>(id);
    }
    GLint disjoint = 0;
    glGetIntegerv(GL_GPU_DISJOINT_EXT, &disjoint);  // clears the flag: only later events count
    return timer;
}

void GpuTimer::begin() {
    if (!supported() || active_ || pending_[static_cast<std::size_t>(next_)]) return;
    glBeginQuery(GL_TIME_ELAPSED_EXT, queries_[static_cast<std::size_t>(next_)].get());
    active_ = true;
}

void GpuTimer::end() {
    if (!active_) return;
    glEndQuery(GL_TIME_ELAPSED_EXT);
    active_ = false;
    pending_[static_cast<std::size_t>(next_)] = true;
    next_ = (next_ + 1) % depth;
}

std::optional<double> GpuTimer::read() {
    const auto k = static_cast<std::size_t>(oldest_);
    if (!pending_[k]) return std::nullopt;
    GLuint available = 0;
    glGetQueryObjectuiv(queries_[k].get(), GL_QUERY_RESULT_AVAILABLE, &available);
    if (!available) return std::nullopt;
    GLuint ns = 0;  // 32 bits hold 4.29 s, far beyond a frame
    glGetQueryObjectuiv(queries_[k].get(), GL_QUERY_RESULT, &ns);
    pending_[k] = false;
    oldest_ = (oldest_ + 1) % depth;
    GLint disjoint = 0;
    glGetIntegerv(GL_GPU_DISJOINT_EXT, &disjoint);
    if (disjoint) return std::nullopt;
    return static_cast<double>(ns) * 1e-9;
}

}  // namespace puddle::gpu
