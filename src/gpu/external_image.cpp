#include "gpu/external_image.hpp"

#include <drm_fourcc.h>

#include <utility>
#include <vector>

#include "gpu/device.hpp"
#include "gpu/gl.hpp"
#include "gpu/gl_debug_labels.hpp"
#include "gpu/gl_errors.hpp"
#include "gpu/gl_extensions.hpp"

namespace puddle::gpu {

namespace {

const char* egl_error_text(EGLint e) {
    switch (e) {
        case EGL_BAD_MATCH:
            return "EGL_BAD_MATCH";
        case EGL_BAD_PARAMETER:
            return "EGL_BAD_PARAMETER";
        case EGL_BAD_ACCESS:
            return "EGL_BAD_ACCESS";
        case EGL_BAD_ALLOC:
            return "EGL_BAD_ALLOC";
        case EGL_BAD_DISPLAY:
            return "EGL_BAD_DISPLAY";
        case EGL_BAD_CONTEXT:
            return "EGL_BAD_CONTEXT";
        default:
            return "EGL error";
    }
}

}  // namespace

ExternalImageSupport Device::external_image_support() const {
    ExternalImageSupport s;
    const EGLDisplay display = eglGetCurrentDisplay();
    const char* egl = display != EGL_NO_DISPLAY ? eglQueryString(display, EGL_EXTENSIONS) : nullptr;
    const GlExtensions& e = *extensions_;
    const bool entry = e.eglCreateImageKHR && e.eglDestroyImageKHR && e.glEGLImageTargetTexture2DOES;
    s.external_sampler = entry && caps_.has("GL_OES_EGL_image_external_essl3");
    s.dmabuf_import = s.external_sampler && has_extension(egl, "EGL_EXT_image_dma_buf_import");
    s.texture_images = s.external_sampler && has_extension(egl, "EGL_KHR_gl_texture_2D_image");
    return s;
}

ExternalImage::ExternalImage(ExternalImage&& o) noexcept
    : extensions_(std::move(o.extensions_)),
      display_(std::exchange(o.display_, nullptr)),
      image_(std::exchange(o.image_, nullptr)),
      texture_(std::move(o.texture_)) {}

ExternalImage& ExternalImage::operator=(ExternalImage&& o) noexcept {
    if (this != &o) {
        reset();
        extensions_ = std::move(o.extensions_);
        display_ = std::exchange(o.display_, nullptr);
        image_ = std::exchange(o.image_, nullptr);
        texture_ = std::move(o.texture_);
    }
    return *this;
}

ExternalImage::~ExternalImage() {
    reset();
}

void ExternalImage::reset() {
    texture_ = Texture();  // the texture lets go of the image first
    if (image_)
        extensions_->eglDestroyImageKHR(static_cast<EGLDisplay>(display_), static_cast<EGLImage>(image_));
    image_ = nullptr;
}

Result<ExternalImage> Device::create_external_image(const ExternalImageDesc& desc) {
    const GlExtensions& e = *extensions_;
    if (!e.eglCreateImageKHR || !e.eglDestroyImageKHR || !e.glEGLImageTargetTexture2DOES)
        return make_error(ExitCode::Runtime, "gpu: external image '{}': EGL image entry points missing",
                          desc.label);
    const EGLDisplay display = eglGetCurrentDisplay();
    EGLImage image = EGL_NO_IMAGE_KHR;
    if (desc.source) {
        const EGLint attribs[] = {EGL_GL_TEXTURE_LEVEL_KHR, 0, EGL_NONE};
        image = e.eglCreateImageKHR(
            display, eglGetCurrentContext(), EGL_GL_TEXTURE_2D_KHR,
            reinterpret_cast<EGLClientBuffer>(static_cast<std::uintptr_t>(desc.source->id())), attribs);
    } else {
        std::vector<EGLint> a = {
            EGL_WIDTH,
            desc.width,
            EGL_HEIGHT,
            desc.height,
            EGL_LINUX_DRM_FOURCC_EXT,
            static_cast<EGLint>(desc.format == DmabufFormat::Nv12 ? DRM_FORMAT_NV12 : DRM_FORMAT_YUYV),
            EGL_YUV_COLOR_SPACE_HINT_EXT,
            desc.bt709 ? EGL_ITU_REC709_EXT : EGL_ITU_REC601_EXT,
            EGL_SAMPLE_RANGE_HINT_EXT,
            desc.full_range ? EGL_YUV_FULL_RANGE_EXT : EGL_YUV_NARROW_RANGE_EXT,
            EGL_DMA_BUF_PLANE0_FD_EXT,
            desc.planes[0].fd,
            EGL_DMA_BUF_PLANE0_OFFSET_EXT,
            static_cast<EGLint>(desc.planes[0].offset),
            EGL_DMA_BUF_PLANE0_PITCH_EXT,
            static_cast<EGLint>(desc.planes[0].pitch)};
        if (desc.planes[1].fd >= 0) {
            a.insert(a.end(), {EGL_DMA_BUF_PLANE1_FD_EXT, desc.planes[1].fd, EGL_DMA_BUF_PLANE1_OFFSET_EXT,
                               static_cast<EGLint>(desc.planes[1].offset), EGL_DMA_BUF_PLANE1_PITCH_EXT,
                               static_cast<EGLint>(desc.planes[1].pitch)});
        }
        a.push_back(EGL_NONE);
        image = e.eglCreateImageKHR(display, EGL_NO_CONTEXT, EGL_LINUX_DMA_BUF_EXT, nullptr, a.data());
    }
    if (image == EGL_NO_IMAGE_KHR)
        return make_error(ExitCode::Runtime, "gpu: external image '{}': eglCreateImageKHR: {}", desc.label,
                          egl_error_text(eglGetError()));
    ExternalImage out;
    out.extensions_ = extensions_;
    out.display_ = display;
    out.image_ = image;
    GLuint id = 0;
    glGenTextures(1, &id);
    out.texture_.id_ = GlHandle<detail::delete_texture>(id);
    out.texture_.desc_ = TextureDesc{.label = desc.label,
                                     .kind = TextureKind::External,
                                     .width = desc.source ? desc.source->width() : desc.width,
                                     .height = desc.source ? desc.source->height() : desc.height};
    (void)take_gl_error();
    glBindTexture(GL_TEXTURE_EXTERNAL_OES, id);
    e.glEGLImageTargetTexture2DOES(GL_TEXTURE_EXTERNAL_OES, static_cast<GLeglImageOES>(image));
    // A driver may make the image but refuse it as a texture (a format its sampler cannot read).
    if (const GLenum error = take_gl_error(); error != GL_NO_ERROR)
        return make_error(exit_code_for(error),
                          "gpu: external image '{}' ({}x{}): glEGLImageTargetTexture2DOES: {}", desc.label,
                          out.texture_.width(), out.texture_.height(), gl_error_name(error));
    glTexParameteri(GL_TEXTURE_EXTERNAL_OES, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_EXTERNAL_OES, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    label_object(*extensions_, GL_TEXTURE, id, desc.label);
    return out;
}

}  // namespace puddle::gpu
