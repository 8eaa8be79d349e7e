#include "app/version.hpp"
namespace puddle::app {
std::string_view version() {
    return PUDDLE_VERSION;
}
}  // namespace puddle::app
