#include "gpu/buffer.hpp"

#include <cassert>

#include "gpu/gl.hpp"

namespace puddle::gpu {

namespace detail {
void delete_buffer(std::uint32_t id) {
    glDeleteBuffers(1, &id);
}
}  // namespace detail

void Buffer::write(std::span<const std::byte> data, std::size_t offset) {
    assert(offset + data.size() <= size_);
    glBindBuffer(GL_UNIFORM_BUFFER, id());
    glBufferSubData(GL_UNIFORM_BUFFER, static_cast<GLintptr>(offset), static_cast<GLsizeiptr>(data.size()),
                    data.data());
}

}  // namespace puddle::gpu
