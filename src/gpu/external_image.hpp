#pragma once
// An EGLImage and the GL_TEXTURE_EXTERNAL_OES texture that samples it (samplerExternalOES in GLSL):
// how camera buffers reach the GPU without a copy. Made by Device::create_external_image from a dmabuf
// (EGL_EXT_image_dma_buf_import) or, where dmabuf import is missing (llvmpipe), from a GL texture
// (EGL_KHR_gl_texture_2D_image), which exercises the same sampler path. Move-only; destroys the image.

#include <cstdint>
#include <memory>
#include <string>

#include "gpu/texture.hpp"

namespace puddle::gpu {

struct GlExtensions;  // gpu/gl_extensions.hpp, private to the gpu layer

// What the current EGL display and GL context can import (Device::external_image_support).
struct ExternalImageSupport {
    bool external_sampler = false;  // GL_OES_EGL_image_external_essl3
    bool dmabuf_import = false;     // EGL_EXT_image_dma_buf_import
    bool texture_images = false;    // EGL_KHR_gl_texture_2D_image
};

struct DmabufPlane {
    int fd = -1;
    std::uint32_t offset = 0, pitch = 0;
};

// The layouts a camera's dmabuf comes in (drm_fourcc.h's DRM_FORMAT_YUYV and DRM_FORMAT_NV12 to EGL).
enum class DmabufFormat { Yuyv, Nv12 };

struct ExternalImageDesc {
    std::string label;
    // Either a dmabuf (fd >= 0 in planes[0]) in this layout ...
    DmabufFormat format = DmabufFormat::Yuyv;
    int width = 0, height = 0;
    DmabufPlane planes[2];
    bool bt709 = false;       // EGL_YUV_COLOR_SPACE_HINT_EXT
    bool full_range = false;  // EGL_SAMPLE_RANGE_HINT_EXT
    // ... or a GL texture of this context (level 0).
    const Texture* source = nullptr;
};

class ExternalImage {
public:
    ExternalImage() = default;
    ExternalImage(ExternalImage&& o) noexcept;
    ExternalImage& operator=(ExternalImage&& o) noexcept;
    ExternalImage(const ExternalImage&) = delete;
    ExternalImage& operator=(const ExternalImage&) = delete;
    ~ExternalImage();
    // Kind External: bind it like any texture; the sampler converts YUV to RGB.
    const Texture& texture() const { return texture_; }
    explicit operator bool() const { return image_ != nullptr; }

private:
    friend class Device;
    void reset();
    std::shared_ptr<const GlExtensions> extensions_;  // eglDestroyImageKHR
    void* display_ = nullptr;                         // EGLDisplay
    void* image_ = nullptr;                           // EGLImage
    Texture texture_;
};

}  // namespace puddle::gpu
