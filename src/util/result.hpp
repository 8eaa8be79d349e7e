#pragma once
// Fallible start-up returns values, not exceptions: Result<T> holds a T or an Error whose message reads
// "module: what failed: why" and whose exit code is the one documented in the README.

#include <fmt/format.h>

#include <string>
#include <utility>
#include <variant>

namespace puddle {

// Exit codes of the puddle binary (README: "Exit codes").
// GpuMemory: a texture or buffer did not fit in GPU memory (GL_OUT_OF_MEMORY); smaller sizes may.
enum class ExitCode : int { Ok = 0, Runtime = 1, Config = 2, Asset = 3, Display = 4, GpuMemory = 5 };

struct Error {
    std::string message;
    ExitCode code = ExitCode::Runtime;
};

template <class... Args>
Error make_error(ExitCode code, fmt::format_string<Args...> f, Args&&... args) {
    return Error{fmt::format(f, std::forward<Args>(args)...), code};
}

template <class T>
class [[nodiscard]] Result {
public:
    Result(T value) : v_(std::move(value)) {}
    Result(Error error) : v_(std::move(error)) {}
    bool ok() const { return v_.index() == 0; }
    explicit operator bool() const { return ok(); }
    // value(), * and -> need ok(): on an error they throw std::bad_variant_access.
    T& value() & { return std::get<0>(v_); }
    const T& value() const& { return std::get<0>(v_); }
    T&& value() && { return std::get<0>(std::move(v_)); }
    T& operator*() & { return value(); }
    const T& operator*() const& { return value(); }
    T* operator->() { return &value(); }
    const T* operator->() const { return &value(); }
    const Error& error() const { return std::get<1>(v_); }

private:
    std::variant<T, Error> v_;
};

template <>
class [[nodiscard]] Result<void> {
public:
    Result() = default;
    Result(Error error) : error_(std::move(error)), ok_(false) {}
    bool ok() const { return ok_; }
    explicit operator bool() const { return ok_; }
    const Error& error() const { return error_; }

private:
    Error error_;
    bool ok_ = true;
};

}  // namespace puddle
