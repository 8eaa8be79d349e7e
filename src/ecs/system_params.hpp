#pragma once
// A system's parameters say what it reads and writes; this header turns a plain function into a
// schedule entry by fetching each parameter from the World (as EnTT's organizer and Bevy's SystemParam
// do):
//   const T&   reads the resource T
//   T&         writes the resource T
//   World&     the whole world (entity storage: spawning and despawning)
// The resources are looked up every run (a hash lookup each, no allocation), so a resource replaced
// by a plugin or a test is seen on the next frame. A missing resource asserts in debug builds, like
// World::resource.

#include <cxxabi.h>

#include <cstdlib>
#include <memory>
#include <string>
#include <type_traits>
#include <typeinfo>
#include <vector>

#include "ecs/world.hpp"

namespace puddle::ecs {

// The readable name of a type for describe(): "puddle::systems::FrameClock" becomes "FrameClock".
template <class T>
std::string type_name() {
    int status = 0;
    std::unique_ptr<char, void (*)(void*)> demangled(
        abi::__cxa_demangle(typeid(T).name(), nullptr, nullptr, &status), std::free);
    std::string name = status == 0 && demangled ? demangled.get() : typeid(T).name();
    // Drop the namespaces; template arguments keep theirs, which is fine for a log line.
    const auto template_start = name.find('<');
    const auto last_scope = name.rfind("::", template_start);
    return last_scope == std::string::npos ? name : name.substr(last_scope + 2);
}

// What one system reads and writes, by resource name, in parameter order.
struct SystemAccess {
    std::vector<std::string> reads;
    std::vector<std::string> writes;
    bool world = false;  // takes the whole World
};

namespace detail {

template <class P>
decltype(auto) fetch(World& world) {
    using R = std::remove_cvref_t<P>;
    static_assert(std::is_lvalue_reference_v<P>, "a system takes resources by reference: const T& or T&");
    if constexpr (std::is_same_v<R, World>)
        return (world);
    else
        return (world.resource<R>());
}

template <class P>
void record(SystemAccess& access) {
    using R = std::remove_cvref_t<P>;
    if constexpr (std::is_same_v<R, World>)
        access.world = true;
    else if constexpr (std::is_const_v<std::remove_reference_t<P>>)
        access.reads.push_back(type_name<R>());
    else
        access.writes.push_back(type_name<R>());
}

}  // namespace detail

template <class Result, class... Params>
SystemAccess access_of(Result (*)(Params...)) {
    SystemAccess access;
    (detail::record<Params>(access), ...);
    return access;
}

// Calls `fn` with its parameters fetched from `world`; the result, if any, is discarded.
template <class Result, class... Params>
void call_with_resources(Result (*fn)(Params...), World& world) {
    fn(detail::fetch<Params>(world)...);
}

}  // namespace puddle::ecs
