#pragma once
// What this GPU and driver can do, probed once when the Device is made. Systems pick formats and
// paths from it (a Raspberry Pi has float render targets but no filtering of 32-bit float textures).

#include <string>

namespace puddle::gpu {

struct Capabilities {
    std::string vendor, renderer, version, glsl_version;
    int major = 3, minor = 0;
    bool float_render_targets = false;  // RG32F/RGBA32F/RGBA16F colour attachments (EXT_color_buffer_float)
    bool half_float_render_targets = false;  // RGBA16F colour attachments (EXT_color_buffer_half_float too)
    bool float_linear_filtering = false;     // GL_LINEAR on 32-bit float textures (OES_texture_float_linear)
    bool srgb_textures = true;               // core in GLES 3.0
    bool timer_queries = false;              // EXT_disjoint_timer_query
    bool external_images = false;            // OES_EGL_image_external_essl3 (camera frames, dmabuf)
    bool debug_labels = false;               // KHR_debug: glObjectLabel
    bool anisotropic_filtering = false;      // EXT_texture_filter_anisotropic
    float max_anisotropy = 1.0f;
    int max_texture_size = 2048;   // GL_MAX_TEXTURE_SIZE (2048 is the GLES 3.0 minimum)
    int max_cube_map_size = 2048;  // GL_MAX_CUBE_MAP_TEXTURE_SIZE

    bool has(const char* extension) const;
    std::string extensions;  // space separated, as the driver reported them
    // One line for the start-up log.
    std::string summary() const;
};

// Reads the current context. `forbid_float_targets` pretends EXT_color_buffer_float is missing, so tests
// and `--set gpu.float_targets=false` exercise the fallback paths on any machine.
Capabilities probe_capabilities(bool forbid_float_targets);

}  // namespace puddle::gpu
