#include "bench/camera_benchmarks.hpp"

#include <fmt/format.h>

#include <cstdio>
#include <vector>

#include "bench/bench_engine.hpp"
#include "camera/mjpeg_decoder.hpp"
#include "camera/mjpeg_encoder.hpp"
#include "systems/sky/camera_environment.hpp"

namespace puddle::bench {

using params::Params;

namespace {

// --- camera frames: what one 1280x720 camera frame costs -------------------------------------
// cpu: the copy (glTexSubImage2D of a YUYV frame, padded rows as drivers give them) or the MJPEG decode;
// gpu: the YUV conversion pass plus the six small environment cube faces and their mipmaps. The
// zero-copy path needs a dmabuf exporter; where EGL has no dmabuf import (llvmpipe), the external
// sampler is measured over an EGLImage of a GL texture, which is its sampling cost without the import.
constexpr glm::ivec2 camera_size{1280, 720};

struct CameraBench {
    systems::CameraEnvironment env;
    std::vector<std::byte> yuyv;
    camera::CameraImage image;
};

std::unique_ptr<CameraBench> camera_current;  // lives with the current engine, released before it

CameraBench* camera_bench(benchmark::State& state) {
    Bench* b = bench_for(sizes[0], state);
    if (!b) return nullptr;
    if (camera_current) return camera_current.get();
    camera_current = std::make_unique<CameraBench>();
    CameraBench* cb = camera_current.get();
    if (auto r = systems::build_camera_pipelines(b->engine->device(), cb->env); !r) {
        state.SkipWithError(r.error().message.c_str());
        return nullptr;
    }
    const int stride = camera_size.x * 2 + 64;
    cb->yuyv.assign(static_cast<std::size_t>(stride) * camera_size.y, std::byte{128});
    for (std::size_t i = 0; i < cb->yuyv.size(); i += 7) cb->yuyv[i] = std::byte(i & 0xff);
    cb->image = {.layout = camera::PixelLayout::Yuyv,
                 .width = camera_size.x,
                 .height = camera_size.y,
                 .stride = stride,
                 .data = cb->yuyv,
                 .matrix = camera::YuvMatrix::Bt709};
    return cb;
}

void bench_camera_copy(benchmark::State& state) {
    CameraBench* cb = camera_bench(state);
    if (!cb) return;
    gpu::Device& device = current_bench()->engine->device();
    measure(state, device, [&] { (void)systems::upload_camera_frame(device, cb->image, cb->env); });
}

void bench_camera_gpu(benchmark::State& state) {
    CameraBench* cb = camera_bench(state);
    if (!cb) return;
    ecs::World& w = current_bench()->engine->world();
    gpu::Device& device = current_bench()->engine->device();
    (void)systems::upload_camera_frame(device, cb->image, cb->env);
    measure(state, device, [&] {
        cb->env.frame = systems::CameraFrame::uploaded;  // as after each new frame
        systems::camera_environment_system(device, w.resource<Params>(), w.resource<systems::Environment>(),
                                           cb->env);
    });
}

void bench_camera_external(benchmark::State& state) {
    CameraBench* cb = camera_bench(state);
    if (!cb) return;
    if (!cb->env.support.texture_images) {
        state.SkipWithError("no EGL_KHR_gl_texture_2D_image / external sampler here");
        return;
    }
    ecs::World& w = current_bench()->engine->world();
    gpu::Device& device = current_bench()->engine->device();
    auto made = device.create_texture(
        {.label = "bench camera frame", .width = camera_size.x, .height = camera_size.y});
    if (!made) {
        state.SkipWithError(made.error().message.c_str());
        return;
    }
    gpu::Texture source = std::move(made).value();
    source.upload(
        std::vector<std::byte>(static_cast<std::size_t>(camera_size.x) * camera_size.y * 4, std::byte{90}));
    auto image = device.create_external_image({.label = "bench camera image", .source = &source});
    if (!image) {
        state.SkipWithError(image.error().message.c_str());
        return;
    }
    (void)systems::upload_camera_frame(device, cb->image, cb->env);  // sizes the colour texture
    measure(state, device, [&] {
        cb->env.pending_import = &*image;
        cb->env.frame = systems::CameraFrame::uploaded;
        systems::camera_environment_system(device, w.resource<Params>(), w.resource<systems::Environment>(),
                                           cb->env);
    });
    cb->env.pending_import = nullptr;
}

void bench_camera_mjpeg(benchmark::State& state) {
    // Fine diagonal stripes on a mid-grey frame: a fair stand-in for a webcam's MJPEG at quality 85.
    static std::vector<std::byte> jpeg;
    if (jpeg.empty()) {
        std::vector<std::uint8_t> rgb(static_cast<std::size_t>(camera_size.x) * camera_size.y * 3);
        const std::size_t stride = static_cast<std::size_t>(camera_size.x) * 3;
        for (std::size_t i = 0; i < rgb.size(); ++i)
            rgb[i] = static_cast<std::uint8_t>(((i % stride) * 7 + (i / stride) * 3) & 0xff);
        jpeg = camera::encode_jpeg(rgb, camera_size.x, camera_size.y, 85);
    }
    camera::MjpegDecoder decoder;
    for (auto _ : state) {
        auto r = decoder.decode(jpeg, camera_size.x, camera_size.y);
        if (!r) {
            state.SkipWithError(r.error().message.c_str());
            return;
        }
        benchmark::DoNotOptimize(decoder.rgba().data());
    }
}

}  // namespace

void release_camera_bench() {
    camera_current.reset();
}

void register_camera_benchmarks() {
    add_benchmark("camera/cpu_copy_yuyv", bench_camera_copy);
    add_benchmark("camera/cpu_decode_mjpeg", bench_camera_mjpeg);
    add_benchmark("camera/gpu_convert_and_cube", bench_camera_gpu);
    add_benchmark("camera/gpu_external_sampler", bench_camera_external);
}

void print_camera_summary(const Collector& c) {
    std::printf("\nOne camera frame at %dx%d, ms\n", camera_size.x, camera_size.y);
    for (const char* key : {"camera/cpu_copy_yuyv", "camera/cpu_decode_mjpeg", "camera/gpu_convert_and_cube",
                            "camera/gpu_external_sampler"}) {
        const auto ms = c.ms(key);
        std::printf("%-30s%s\n", key,
                    ms ? fmt::format("{:>10.2f}", *ms).c_str() : fmt::format("{:>10}", "-").c_str());
    }
}

}  // namespace puddle::bench
