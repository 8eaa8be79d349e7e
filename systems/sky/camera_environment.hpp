#pragma once
// The camera's frame as an environment: upload (a copy with glTexSubImage2D, or a cached EGLImage per
// driver buffer where dmabufs can be imported), YUV to colour in a shader, then a small cube map
// rendered from the image by the chosen mapping and mixed with the static cubemap. The puddle pass
// samples that cube in place of the cubemap while it is active: the puddle shader is unchanged.

#include <cstdint>
#include <optional>
#include <vector>

#include "camera/camera_image.hpp"
#include "gpu/device.hpp"
#include "params/param_store.hpp"
#include "render/pipeline_cache.hpp"
#include "systems/sky/environment_system.hpp"
#include "util/result.hpp"

namespace puddle::systems {

// The camera's cube, per face: at most 256 texels (the reflection is blurred by ripples anyway), and no
// sharper than the sky it is mixed with (environment.camera_blend), so a slow board that asks for small sky
// faces (environment.face_size) also redraws a small cube at every camera frame.
inline constexpr int camera_cube_max_size = 256;
int camera_cube_size(const Environment& sky);

// The camera's passes, each a variant of camera_convert.frag or camera_cube.frag; `convert_external` only
// where the GPU samples external images.
enum class CameraPass { convert_yuyv, convert_nv12, convert_external, cube_planar, cube_mirror_ball };
using CameraPipelines = render::PipelineCache<CameraPass, 5, render::enum_index<CameraPass>>;

// Where the camera environment's set-up stands: the GPU's external-image support not yet asked, the
// pipelines building, everything ready, or disabled by a GPU error (the cubemap stays, for good).
enum class CameraSetup { unprobed, building, ready, failed };
// Where the latest camera frame stands: none (no stream, or its frames were dropped); uploaded and not yet
// converted to colour (YUV frames); converted, its cube not yet drawn; its cube drawn.
enum class CameraFrame { none, uploaded, converted, cube_drawn };

// Resource.
struct CameraEnvironment {
    gpu::Texture plane0, plane1;  // the copied frame: RGBA8 (YUYV pairs), or R8 + RG8 (NV12)
    gpu::Texture colour;          // the converted frame, sRGB, camera size, with mipmaps
    gpu::Texture cube;            // what the puddle reflects while the camera streams: camera_cube_size(sky)
    gpu::Sampler nearest, linear;
    // Asked for at the first camera frame (most runs never need them), built off the frame thread; the
    // cube passes read environment.camera_blend.
    CameraPipelines pipelines;
    std::vector<gpu::ExternalImage> imported;  // per driver buffer (zero-copy path)
    gpu::ExternalImageSupport support;
    bool zero_copy = false;  // dmabuf import available: use it for frames that carry a dmabuf
    CameraSetup setup = CameraSetup::unprobed;

    camera::PixelLayout layout = camera::PixelLayout::Rgba;
    camera::CameraImage pending;  // the uploaded frame's description (data not kept)
    const gpu::ExternalImage* pending_import = nullptr;
    CameraFrame frame = CameraFrame::none;
    std::uint64_t cube_params_revision = 0;

    bool ready() const { return setup == CameraSetup::ready; }
    bool failed() const { return setup == CameraSetup::failed; }
    // The cube the puddle pass should sample, or null for the static cubemap. (A frame uploaded this
    // frame is converted and its cube drawn by the camera environment system before the puddle pass.)
    const gpu::Texture* reflection() const {
        return frame != CameraFrame::none && !failed() && cube ? &cube : nullptr;
    }
};

// Asks for the pipelines on the first call and takes them as they are built (the pipeline cache's poll:
// off the frame thread where background compiles run); nothing while some are still building, then the
// result: an error (a shader that does not build) is returned once, and the cache never builds it again.
std::optional<Result<void>> poll_camera_pipelines(gpu::Device& device, CameraEnvironment& env);
// The same, waiting until they are built (tests and the benchmark).
Result<void> build_camera_pipelines(gpu::Device& device, CameraEnvironment& env);

// Input stage: hands one new frame to the GPU (a copy, or an import of its dmabuf). No conversion yet.
Result<void> upload_camera_frame(gpu::Device& device, const camera::CameraImage& image,
                                 CameraEnvironment& env);
// The stream ended: forget its frames and imports; the puddle goes back to the cubemap.
void drop_camera_frames(CameraEnvironment& env);

// Render stage, before the puddle: converts the newest frame and renders the cube when something changed.
void camera_environment_system(gpu::Device& device, const params::Params& params, const Environment& sky,
                               CameraEnvironment& env);

}  // namespace puddle::systems
