// DRM/KMS + GBM: fullscreen on a bare console with no window system, the usual signage set-up.
// EGL renders into a gbm_surface; each presented buffer becomes a DRM framebuffer that is shown with a
// vblank-paced page flip. The CRTC found at start-up is put back on exit so the console returns.

#include <fcntl.h>
#include <fmt/format.h>
#include <gbm.h>
#include <poll.h>
#include <spdlog/spdlog.h>
#include <unistd.h>
#include <xf86drm.h>
#include <xf86drmMode.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <system_error>
#include <utility>
#include <vector>

#include "platform/display.hpp"
#include "platform/drm_inventory.hpp"
#include "platform/drm_names.hpp"
#include "platform/egl_context.hpp"
#include "platform/kms_mode.hpp"
#include "util/unique_fd.hpp"

namespace puddle::platform {

namespace {

std::string errno_text(int err) {
    return std::error_code(err, std::generic_category()).message();
}

// unique_ptr deleter for a C API's free function.
template <auto Free>
struct FreeWith {
    template <class T>
    void operator()(T* p) const {
        Free(p);
    }
};
using ResourcesPtr = std::unique_ptr<drmModeRes, FreeWith<drmModeFreeResources>>;
using ConnectorPtr = std::unique_ptr<drmModeConnector, FreeWith<drmModeFreeConnector>>;
using EncoderPtr = std::unique_ptr<drmModeEncoder, FreeWith<drmModeFreeEncoder>>;
using CrtcPtr = std::unique_ptr<drmModeCrtc, FreeWith<drmModeFreeCrtc>>;
using PropertiesPtr = std::unique_ptr<drmModeObjectProperties, FreeWith<drmModeFreeObjectProperties>>;
using PropertyPtr = std::unique_ptr<drmModePropertyRes, FreeWith<drmModeFreeProperty>>;
using GbmDevicePtr = std::unique_ptr<gbm_device, FreeWith<gbm_device_destroy>>;
using GbmSurfacePtr = std::unique_ptr<gbm_surface, FreeWith<gbm_surface_destroy>>;

Result<UniqueFd> open_card(const std::string& path) {
    const int fd = ::open(path.c_str(), O_RDWR | O_CLOEXEC);
    if (fd < 0) return make_error(ExitCode::Display, "kms: {}: open: {}", path, errno_text(errno));
    return UniqueFd(fd);
}

std::vector<ConnectorPtr> get_connectors(int fd, const drmModeRes& res) {
    std::vector<ConnectorPtr> connectors;
    for (int i = 0; i < res.count_connectors; ++i)
        if (ConnectorPtr c{drmModeGetConnector(fd, res.connectors[i])}) connectors.push_back(std::move(c));
    return connectors;
}

// Master is what lets us modeset; the first opener gets it, otherwise it must be free to take.
bool acquire_master(int fd) {
    return drmIsMaster(fd) || drmSetMaster(fd) == 0;
}

// Why a card cannot be used, or nothing when it can (then `connector` names the first connected one).
// The card is read as `puddle --check` reads it (drm_inventory); only taking master is the probe's own.
std::optional<std::string> check_card(const std::string& path, std::string& connector) {
    auto fd = open_card(path);
    if (!fd) {  // the probe's reason has no "kms: " prefix: the line that reports it adds one
        std::string_view reason = fd.error().message;
        if (reason.starts_with("kms: ")) reason.remove_prefix(std::string_view("kms: ").size());
        return std::string(reason);
    }
    const DrmCardInfo card = read_drm_card(fd->get(), path);
    if (card.status == DrmCardStatus::NoOutputs)
        return fmt::format("{}: cannot modeset (render-only device?)", path);
    const auto shown =
        std::find_if(card.connectors.begin(), card.connectors.end(), [](const DrmConnectorInfo& c) {
            return c.connected && !c.modes.empty();  // as is_connected
        });
    if (shown == card.connectors.end()) return fmt::format("{}: no connected connector", path);
    connector = shown->name;
    if (!acquire_master(fd->get()))
        return fmt::format("{}: held by another process (is a desktop running?)", path);
    drmDropMaster(fd->get());
    return std::nullopt;
}

// The card's connectors, in its order, for pick_connector (kms_mode.hpp).
Result<ConnectorPtr> take_connector(int fd, const std::string& card, const drmModeRes& res,
                                    const std::string& wanted) {
    auto connectors = get_connectors(fd, res);
    std::vector<const drmModeConnector*> views;
    for (const auto& c : connectors) views.push_back(c.get());
    auto chosen = pick_connector(views, card, wanted);
    if (!chosen) return chosen.error();
    return std::move(connectors[*chosen]);
}

// The CRTC already driving the connector, else the first one an encoder of the connector can use.
Result<uint32_t> pick_crtc(int fd, const std::string& card, const drmModeRes& res,
                           const drmModeConnector& c) {
    if (c.encoder_id != 0) {
        const EncoderPtr encoder{drmModeGetEncoder(fd, c.encoder_id)};
        if (encoder && encoder->crtc_id != 0) return encoder->crtc_id;
    }
    for (int i = 0; i < c.count_encoders; ++i) {
        const EncoderPtr encoder{drmModeGetEncoder(fd, c.encoders[i])};
        if (!encoder) continue;
        for (int j = 0; j < res.count_crtcs && j < 32; ++j)
            if (encoder->possible_crtcs & (1u << j)) return res.crtcs[j];
    }
    return make_error(ExitCode::Display, "kms: {}: no CRTC can drive {}", card, connector_name(c));
}

// The CRTC as it was before we took it (usually the console); put back on destruction.
class SavedCrtc {
public:
    SavedCrtc() = default;
    SavedCrtc(int fd, uint32_t connector, CrtcPtr crtc)
        : fd_(fd), connector_(connector), crtc_(std::move(crtc)) {}
    SavedCrtc(SavedCrtc&&) noexcept = default;
    SavedCrtc& operator=(SavedCrtc&& other) noexcept {
        if (this != &other) {
            restore();
            fd_ = other.fd_;
            connector_ = other.connector_;
            crtc_ = std::move(other.crtc_);
        }
        return *this;
    }
    ~SavedCrtc() { restore(); }

private:
    void restore() {
        if (!crtc_) return;
        drmModeCrtc& c = *crtc_;
        const int rc = c.mode_valid && c.buffer_id != 0
                           ? drmModeSetCrtc(fd_, c.crtc_id, c.buffer_id, c.x, c.y, &connector_, 1, &c.mode)
                           : drmModeSetCrtc(fd_, c.crtc_id, 0, 0, 0, nullptr, 0, nullptr);  // it was off
        if (rc != 0) spdlog::warn("kms: restoring CRTC {}: {}", c.crtc_id, errno_text(-rc));
        crtc_.reset();
    }
    int fd_ = -1;  // not owned
    uint32_t connector_ = 0;
    CrtcPtr crtc_;
};

// A buffer locked from the gbm_surface (being scanned out, or about to be); released back on reset.
class LockedBo {
public:
    LockedBo() = default;
    LockedBo(gbm_surface* surface, gbm_bo* bo) : surface_(surface), bo_(bo) {}
    LockedBo(LockedBo&& other) noexcept
        : surface_(std::exchange(other.surface_, nullptr)), bo_(std::exchange(other.bo_, nullptr)) {}
    LockedBo& operator=(LockedBo&& other) noexcept {
        if (this != &other) {
            reset();
            surface_ = std::exchange(other.surface_, nullptr);
            bo_ = std::exchange(other.bo_, nullptr);
        }
        return *this;
    }
    ~LockedBo() { reset(); }

    gbm_bo* get() const { return bo_; }
    explicit operator bool() const { return bo_ != nullptr; }
    void reset() {
        if (bo_) gbm_surface_release_buffer(surface_, bo_);
        bo_ = nullptr;
    }

private:
    gbm_surface* surface_ = nullptr;
    gbm_bo* bo_ = nullptr;
};

// A DRM framebuffer made for a gbm_bo, kept in the bo's user data: gbm buffers are recycled, so each
// needs AddFB once, and gbm calls the destroy hook when the surface frees the bo.
struct BoFramebuffer {
    int fd = -1;
    uint32_t id = 0;

    static void destroy(gbm_bo* /*bo*/, void* data) {
        auto* fb = static_cast<BoFramebuffer*>(data);
        drmModeRmFB(fb->fd, fb->id);
        delete fb;
    }
};

// DRM_FORMAT_MOD_INVALID, spelled out: the macro's old-style cast trips -Wold-style-cast.
constexpr uint64_t kModifierInvalid = 0x00ffffffffffffffULL;

Result<uint32_t> framebuffer_for(int fd, const std::string& card, gbm_bo* bo) {
    if (auto* fb = static_cast<BoFramebuffer*>(gbm_bo_get_user_data(bo))) return fb->id;

    const uint32_t width = gbm_bo_get_width(bo);
    const uint32_t height = gbm_bo_get_height(bo);
    const uint32_t format = gbm_bo_get_format(bo);
    const uint64_t modifier = gbm_bo_get_modifier(bo);
    std::array<uint32_t, 4> handles{}, pitches{}, offsets{};
    std::array<uint64_t, 4> modifiers{};
    const int planes = std::clamp(gbm_bo_get_plane_count(bo), 1, 4);
    for (int i = 0; i < planes; ++i) {
        const auto p = static_cast<std::size_t>(i);
        handles[p] = gbm_bo_get_handle_for_plane(bo, i).u32;
        pitches[p] = gbm_bo_get_stride_for_plane(bo, i);
        offsets[p] = gbm_bo_get_offset(bo, i);
        modifiers[p] = modifier;
    }
    uint32_t id = 0;
    int rc = -1;
    // Tiled or compressed buffers (Raspberry Pi, Intel) must say so; plain AddFB2 and the legacy
    // depth/bpp call are fallbacks for older drivers.
    if (modifier != kModifierInvalid)
        rc = drmModeAddFB2WithModifiers(fd, width, height, format, handles.data(), pitches.data(),
                                        offsets.data(), modifiers.data(), &id, DRM_MODE_FB_MODIFIERS);
    if (rc != 0)
        rc = drmModeAddFB2(fd, width, height, format, handles.data(), pitches.data(), offsets.data(), &id, 0);
    const int add_fb2_rc = rc;  // the informative error; the legacy call only knows XRGB8888
    if (rc != 0 && format == GBM_FORMAT_XRGB8888)
        rc = drmModeAddFB(fd, width, height, 24, 32, pitches[0], handles[0], &id);
    if (rc != 0)
        return make_error(ExitCode::Display, "kms: {}: drmModeAddFB2 {}x{}: {}", card, width, height,
                          errno_text(-add_fb2_rc));
    gbm_bo_set_user_data(bo, new BoFramebuffer{fd, id}, &BoFramebuffer::destroy);
    return id;
}

class KmsDisplay final : public Display {
public:
    void make_current() override { (void)egl_.make_current(); }
    Result<std::unique_ptr<gpu::WorkerContext>> create_worker_context() override {
        return egl_.create_worker_context();
    }
    static Result<std::unique_ptr<Display>> create(const DisplayOptions& options);

    ~KmsDisplay() override {
        // The last flip may still be on its way to the screen.
        if (auto waited = flip_pending_ ? wait_for_flip() : Result<void>{}; !waited)
            spdlog::warn("{}", waited.error().message);
        if (!powered_)  // the console needs the output on
            if (auto on = set_dpms(DRM_MODE_DPMS_ON); !on) spdlog::warn("{}", on.error().message);
        saved_crtc_ = SavedCrtc{};  // console back before our framebuffers go away
        front_.reset();
        // Members go in reverse order: EGL, then the gbm surface (removing its framebuffers), the gbm
        // device and finally the card's fd.
    }

    BackendKind kind() const override { return BackendKind::Kms; }
    bool switches_output_power() const override { return true; }
    bool owns_the_console() const override { return true; }
    glm::ivec2 size() const override { return {mode_.hdisplay, mode_.vdisplay}; }
    double refresh_hz() const override { return mode_.vrefresh; }
    gpu::FrameTarget frame_target() const override { return {nullptr, size()}; }
    bool poll_events() override { return true; }  // no window system; signals are handled by the app
    Result<void> present() override;
    Result<void> set_power(bool on) override;
    std::string describe() const override {
        return fmt::format("kms: {} {} {}Hz", card_, connector_name_, mode_name(mode_));
    }

private:
    KmsDisplay() = default;
    Result<void> wait_for_flip();
    Result<void> set_dpms(uint64_t state);

    std::string card_;
    std::string connector_name_;
    uint32_t connector_id_ = 0;
    uint32_t crtc_id_ = 0;
    drmModeModeInfo mode_{};
    bool flip_pending_ = false;  // written by the page-flip event handler
    long frames_shown_ = 0;
    bool modeset_needed_ = true;  // the first frame, and the first after the output was off

    UniqueFd fd_;
    GbmDevicePtr gbm_;
    GbmSurfacePtr surface_;
    EglContext egl_;
    SavedCrtc saved_crtc_;
    LockedBo front_;  // the buffer on screen
};

Result<std::unique_ptr<Display>> KmsDisplay::create(const DisplayOptions& options) {
    std::string card = options.card;
    if (card.empty()) {
        const KmsProbe probe = probe_kms("");
        if (probe.card.empty())
            return make_error(ExitCode::Display, "kms: no card can modeset: {}", probe.reason);
        card = probe.card;
    }
    // The object owns each piece as soon as it exists, so an early return cleans up what was made.
    std::unique_ptr<KmsDisplay> d{new KmsDisplay()};
    d->card_ = card;
    auto fd = open_card(card);
    if (!fd) return fd.error();
    d->fd_ = std::move(*fd);
    const int drm = d->fd_.get();
    const ResourcesPtr res{drmModeGetResources(drm)};
    if (!res)
        return make_error(ExitCode::Display, "kms: {}: drmModeGetResources: {} (render-only device?)", card,
                          errno_text(errno));
    if (!acquire_master(drm))
        return make_error(ExitCode::Display, "kms: {}: drmSetMaster: {} (is a desktop running?)", card,
                          errno_text(errno));
    auto connector = take_connector(drm, card, *res, options.connector);
    if (!connector) return connector.error();
    auto mode = pick_mode(card, **connector, options);
    if (!mode) return mode.error();
    auto crtc = pick_crtc(drm, card, *res, **connector);
    if (!crtc) return crtc.error();
    d->connector_id_ = (*connector)->connector_id;
    d->connector_name_ = connector_name(**connector);
    d->mode_ = *mode;
    d->crtc_id_ = *crtc;

    d->gbm_.reset(gbm_create_device(drm));
    if (!d->gbm_)
        return make_error(ExitCode::Display, "kms: {}: gbm_create_device: {}", card, errno_text(errno));
    d->surface_.reset(gbm_surface_create(d->gbm_.get(), d->mode_.hdisplay, d->mode_.vdisplay,
                                         GBM_FORMAT_XRGB8888, GBM_BO_USE_SCANOUT | GBM_BO_USE_RENDERING));
    if (!d->surface_)
        return make_error(ExitCode::Display, "kms: {}: gbm_surface_create {}x{} XRGB8888: {}", card,
                          d->mode_.hdisplay, d->mode_.vdisplay, errno_text(errno));

    auto egl = EglContext::create({.platform = EGL_PLATFORM_GBM_KHR,
                                   .native_display = d->gbm_.get(),
                                   .window_surface = true,
                                   .native_visual = static_cast<EGLint>(GBM_FORMAT_XRGB8888)});
    if (!egl) return make_error(ExitCode::Display, "kms: {}: {}", card, egl.error().message);
    d->egl_ = std::move(*egl);
    if (auto attached = d->egl_.attach_window(d->surface_.get()); !attached)
        return make_error(ExitCode::Display, "kms: {}: {}", card, attached.error().message);

    // Saved last: nothing is changed on screen until the first present().
    d->saved_crtc_ = SavedCrtc(drm, d->connector_id_, CrtcPtr{drmModeGetCrtc(drm, d->crtc_id_)});
    return std::unique_ptr<Display>(std::move(d));
}

Result<void> KmsDisplay::wait_for_flip() {
    drmEventContext events{};
    events.version = 2;  // page_flip_handler is all we use
    events.page_flip_handler = [](int, unsigned, unsigned, unsigned, void* data) {
        *static_cast<bool*>(data) = false;
    };
    while (flip_pending_) {
        pollfd p{fd_.get(), POLLIN, 0};
        const int n = ::poll(&p, 1, 1000);
        if (n < 0 && errno == EINTR) continue;  // a signal (the app's quit) must not lose the event
        if (n < 0) return make_error(ExitCode::Display, "kms: {}: poll: {}", card_, errno_text(errno));
        if (n == 0) return make_error(ExitCode::Display, "kms: {}: page flip not done after 1 s", card_);
        if (drmHandleEvent(fd_.get(), &events) != 0)
            return make_error(ExitCode::Display, "kms: {}: drmHandleEvent: {}", card_, errno_text(errno));
    }
    return {};
}

// The connector's standard "DPMS" property (kernel documentation, "KMS Properties"): legacy, but every
// driver has it, and on atomic drivers it is the helpers' switch of the CRTC's ACTIVE state.
Result<void> KmsDisplay::set_dpms(uint64_t state) {
    const PropertiesPtr props{
        drmModeObjectGetProperties(fd_.get(), connector_id_, DRM_MODE_OBJECT_CONNECTOR)};
    if (!props)
        return make_error(ExitCode::Display, "kms: {}: {}: drmModeObjectGetProperties: {}", card_,
                          connector_name_, errno_text(errno));
    for (uint32_t i = 0; i < props->count_props; ++i) {
        const PropertyPtr prop{drmModeGetProperty(fd_.get(), props->props[i])};
        if (!prop || std::string_view(prop->name) != "DPMS") continue;
        const int rc = drmModeConnectorSetProperty(fd_.get(), connector_id_, prop->prop_id, state);
        if (rc != 0)
            return make_error(ExitCode::Display, "kms: {}: {}: DPMS {}: {}", card_, connector_name_,
                              state == DRM_MODE_DPMS_ON ? "on" : "off", errno_text(-rc));
        return {};
    }
    return make_error(ExitCode::Display, "kms: {}: {} has no DPMS property", card_, connector_name_);
}

Result<void> KmsDisplay::set_power(bool on) {
    if (on == powered_) return {};
    if (!on && flip_pending_)  // the flip in flight lands before the output goes
        if (auto waited = wait_for_flip(); !waited) return waited;
    if (auto r = set_dpms(on ? DRM_MODE_DPMS_ON : DRM_MODE_DPMS_OFF); !r) return r;
    powered_ = on;
    if (on) modeset_needed_ = true;  // the same mode again, with the next frame's buffer
    spdlog::info("kms: {} {} output {}", card_, connector_name_, on ? "on (DPMS on)" : "off (DPMS off)");
    return {};
}

Result<void> KmsDisplay::present() {
    if (!powered_) return {};  // nothing is scanned out; the frame is dropped
    if (!egl_.swap_buffers())
        return make_error(ExitCode::Display, "kms: {}: eglSwapBuffers: {}", card_,
                          egl_error_name(eglGetError()));
    LockedBo next{surface_.get(), gbm_surface_lock_front_buffer(surface_.get())};
    if (!next) return make_error(ExitCode::Display, "kms: {}: gbm_surface_lock_front_buffer failed", card_);
    auto fb = framebuffer_for(fd_.get(), card_, next.get());
    if (!fb) return fb.error();

    if (modeset_needed_) {
        // First frame: a full modeset. Later frames only flip, which waits for vblank and never tears.
        const int rc = drmModeSetCrtc(fd_.get(), crtc_id_, *fb, 0, 0, &connector_id_, 1, &mode_);
        if (rc != 0)
            return make_error(ExitCode::Display, "kms: {}: drmModeSetCrtc {} {}: {}", card_, connector_name_,
                              mode_name(mode_), errno_text(-rc));
        modeset_needed_ = false;
    } else {
        if (flip_pending_)  // a flip that timed out last frame
            if (auto waited = wait_for_flip(); !waited) return waited;
        const int rc = drmModePageFlip(fd_.get(), crtc_id_, *fb, DRM_MODE_PAGE_FLIP_EVENT, &flip_pending_);
        if (rc != 0)
            return make_error(ExitCode::Display, "kms: {}: drmModePageFlip: {}", card_, errno_text(-rc));
        flip_pending_ = true;
        if (auto waited = wait_for_flip(); !waited) {
            front_ = std::move(next);  // queued for scan-out: keep it locked so nobody renders into it
            return waited;
        }
    }
    front_ = std::move(next);  // releases the buffer that was on screen
    // Tests (tests/vm) wait for this line to take a screendump of a known frame.
    spdlog::debug("kms: frame {} on screen", ++frames_shown_);
    return {};
}

}  // namespace

KmsProbe probe_kms(const std::string& preferred_card) {
    const std::vector<std::string> cards =
        preferred_card.empty() ? drm_card_paths() : std::vector{preferred_card};
    if (cards.empty()) return {"", "no /dev/dri/card* devices"};
    std::vector<std::string> reasons;
    for (const std::string& card : cards) {
        std::string connector;
        if (auto why_not = check_card(card, connector)) {
            reasons.push_back(std::move(*why_not));
            continue;
        }
        return {card, fmt::format("{} can modeset, connector {} connected", card, connector)};
    }
    return {"", fmt::format("{}", fmt::join(reasons, "; "))};
}

Result<std::unique_ptr<Display>> create_kms_display(const DisplayOptions& options) {
    return KmsDisplay::create(options);
}

}  // namespace puddle::platform
