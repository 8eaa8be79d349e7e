#include "gpu/pipeline.hpp"

#include "gpu/gl.hpp"

namespace puddle::gpu {

namespace detail {
void delete_program(std::uint32_t id) {
    glDeleteProgram(id);
}
}  // namespace detail

int Pipeline::location(std::string_view uniform) const {
    for (std::size_t i = 0; i < names_.size(); ++i)
        if (names_[i] == uniform) return locations_[i];
    return -1;
}

}  // namespace puddle::gpu
