// Chooses the display backend at start-up. Auto prefers what a signage box wants: a KMS card it can
// own, else a desktop window when there is a desktop, else headless, which always works.

#include "platform/backend_select.hpp"

#include <spdlog/spdlog.h>

#include <cstdlib>
#include <utility>

namespace puddle::platform {

namespace {

constexpr BackendInfo backend_table[] = {
    {BackendKind::Kms, "kms", "fullscreen on a screen through DRM/KMS, no desktop needed",
     create_kms_display},
    {BackendKind::Window, "window", "a window on an X11 desktop", create_window_display},
    {BackendKind::Headless, "headless", "no screen, renders offscreen and writes a PNG",
     create_headless_display},
};

}  // namespace

std::span<const BackendInfo> display_backends() {
    return backend_table;
}

std::string_view backend_name(BackendKind k) {
    if (k == BackendKind::Auto) return "auto";
    for (const BackendInfo& b : backend_table)
        if (b.kind == k) return b.name;
    return "unknown";
}

std::optional<BackendKind> backend_from_name(std::string_view name) {
    if (name == "auto") return BackendKind::Auto;
    for (const BackendInfo& b : backend_table)
        if (b.name == name) return b.kind;
    return std::nullopt;
}

BackendChoice choose_backend(BackendKind requested, const KmsProbe& kms, const char* display_env) {
    if (requested != BackendKind::Auto) return {requested, "requested explicitly", {}};

    const bool has_display = display_env != nullptr && display_env[0] != '\0';
    if (!kms.card.empty()) {
        BackendChoice choice{BackendKind::Kms, kms.reason, {}};
        if (has_display) choice.fallbacks.push_back(BackendKind::Window);
        choice.fallbacks.push_back(BackendKind::Headless);
        return choice;
    }
    if (has_display)
        return {BackendKind::Window,
                fmt::format("{}; DISPLAY={}", kms.reason, display_env),
                {BackendKind::Headless}};
    return {BackendKind::Headless, fmt::format("{}; DISPLAY not set", kms.reason), {}};
}

namespace {

Result<std::unique_ptr<Display>> create_backend(BackendKind kind, const DisplayOptions& options) {
    for (const BackendInfo& b : backend_table)
        if (b.kind == kind) return b.create(options);
    return make_error(ExitCode::Display, "display: no backend for '{}'", backend_name(kind));
}

}  // namespace

Result<std::unique_ptr<Display>> create_display(const DisplayOptions& options) {
    const bool is_auto = options.backend == BackendKind::Auto;
    // Only Auto probes: an explicit --backend kms opens the card itself and reports its own errors.
    const KmsProbe kms = is_auto ? probe_kms(options.card) : KmsProbe{};
    const BackendChoice choice = choose_backend(options.backend, kms, std::getenv("DISPLAY"));
    spdlog::info("display: picked {}: {}", backend_name(choice.kind), choice.reason);

    DisplayOptions resolved = options;
    if (choice.kind == BackendKind::Kms && is_auto) resolved.card = kms.card;  // no second probe

    auto display = create_backend(choice.kind, resolved);
    BackendKind failed = choice.kind;
    for (BackendKind next : choice.fallbacks) {
        if (display.ok()) break;
        spdlog::warn("display: {} failed, falling back to {}: {}", backend_name(failed), backend_name(next),
                     display.error().message);
        display = create_backend(next, resolved);
        failed = next;
    }
    return display;
}

}  // namespace puddle::platform
