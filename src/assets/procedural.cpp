#include "assets/procedural.hpp"

#include <algorithm>
#include <cmath>
#include <system_error>
#include <thread>
#include <vector>

#include "assets/cloud_layer.hpp"
#include "assets/procedural_city.hpp"
#include "assets/procedural_shading.hpp"

namespace puddle::assets {
namespace {

using namespace shading;

// OpenGL cube map face orientation (GLES 3.0 spec, table 3.21): a direction with major axis ma and
// face coordinates sc, tc in [-1, 1]. Row 0 of an image is t = 0, i.e. tc = -1.
Vec3 face_direction(int face, float sc, float tc) {
    switch (face) {
        case 0:
            return {1.0f, -tc, -sc};  // +X
        case 1:
            return {-1.0f, -tc, sc};  // -X
        case 2:
            return {sc, 1.0f, tc};  // +Y
        case 3:
            return {sc, -1.0f, -tc};  // -Y
        case 4:
            return {sc, -tc, 1.0f};  // +Z
        default:
            return {-sc, -tc, -1.0f};  // -Z
    }
}

// The palette, sRGB values chosen by eye, kept in linear light.
struct Palette {
    Vec3 zenith = srgb(8, 12, 30);
    Vec3 mid = srgb(22, 22, 48);      // a bluish-violet band between zenith and glow
    Vec3 horizon = srgb(70, 50, 45);  // sodium light pollution
    Vec3 band = srgb(150, 80, 36);    // the hot orange just above the roofs
    Vec3 cloud_high = srgb(34, 30, 44);
    Vec3 cloud_low = srgb(96, 66, 52);   // cloud bases lit from below by the city
    Vec3 moon = Vec3{3.0f, 2.9f, 2.6f};  // past white: it glints after tone mapping
    Vec3 moon_halo = srgb(120, 130, 160);
};

// Everything that depends on the seed or the face size, computed once per cubemap.
struct Scene {
    std::uint32_t key = 0;
    float face_pix = 0.01f;  // one texel in face coordinates
    Vec3 moon_dir;
    float glow_c1 = 0, glow_s1 = 0, glow_c2 = 0, glow_s2 = 0;  // cos and sin of the glow's phases
    Palette pal;
    city::CityView city;
};

// The city is brighter in some directions (downtown) than in others: 0.8 + 0.22 sin(az + p1) + 0.12 sin(2 az
// + p2), written with the direction's own sine and cosine of azimuth to keep trigonometry out of the texel
// loop.
float city_glow(const Scene& s, Vec3 d) {
    const float r = std::sqrt(d.x * d.x + d.z * d.z);
    if (r < 1e-6f) return 0.8f;
    const float sa = d.x / r, ca = -d.z / r;
    const float s2 = 2.0f * sa * ca, c2 = ca * ca - sa * sa;
    return 0.8f + 0.22f * (sa * s.glow_c1 + ca * s.glow_s1) + 0.12f * (s2 * s.glow_c2 + c2 * s.glow_s2);
}

Vec3 sky(const Scene& s, Vec3 d, float glow) {
    const float up = std::max(d.y, 0.0f);
    Vec3 c = mix(s.pal.mid, s.pal.zenith, smoothstep(0.1f, 0.8f, up));
    const float g = std::exp(-up * 7.0f) * glow;
    c = mix(c, s.pal.horizon, clamp01(g));
    // A bright, narrow band just above the skyline where the city's light scatters most.
    return c + s.pal.band * (0.5f * std::exp(-up * 25.0f) * glow);
}

// How much a cloud may cover the sky in direction d: none at the horizon, where the deck is too far to
// see, rising to 0.85 from about 7 degrees up (the layer's own coverage multiplies it).
float cloud_fade(Vec3 d) {
    return smoothstep(0.01f, 0.12f, d.y) * 0.85f;
}

float cloud_density(const Image& layer, Vec3 d) {
    if (d.y < 0.01f) return 0.0f;
    const auto uv = cloud_layer_uv(d.x, d.y, d.z);
    return cloud_coverage(layer, uv[0], uv[1]) * cloud_fade(d);
}

Vec3 clouds_over(const Scene& s, Vec3 d, Vec3 c, float density, float glow, float moon_near) {
    const float low = std::exp(-std::max(d.y, 0.0f) * 4.0f);
    Vec3 col = mix(s.pal.cloud_high, s.pal.cloud_low * glow, low);
    col = col + s.pal.moon_halo * (0.6f * moon_near);  // silver edges around the moon
    return mix(c, col, density);
}

// Stars on a per-face grid, at most one per cell; the 3x3 neighbourhood keeps halos whole across cells.
Vec3 stars(const Scene& s, int face, float sc, float tc) {
    constexpr int grid = 28;
    constexpr float cell = 2.0f / grid;
    // Only the cells within reach of the widest star (3 sigma) can light this texel: usually just one.
    const float reach = 3.0f * 0.8f * s.face_pix;
    const auto cell_of = [&](float v) {
        return std::clamp(static_cast<int>((v + 1.0f) / cell), 0, grid - 1);
    };
    Vec3 sum;
    for (int j = cell_of(tc - reach); j <= cell_of(tc + reach); ++j) {
        for (int i = cell_of(sc - reach); i <= cell_of(sc + reach); ++i) {
            const std::uint32_t h = hash(as_u32(i), as_u32(j), s.key ^ (0x57a2U + as_u32(face)));
            if (unit(h) > 0.15f) continue;  // a city sky: few stars
            const float b = unit(hash(h, 1U));
            const float bright = 0.05f + 1.5f * b * b * b * b;
            const float sigma = s.face_pix * (0.45f + 0.35f * b);
            // Kept off the face edges, so no star is cut in half by a seam.
            const float margin = 3.0f * sigma;
            const float px = std::clamp(-1.0f + cell * (static_cast<float>(i) + unit(hash(h, 2U))),
                                        -1.0f + margin, 1.0f - margin);
            const float py = std::clamp(-1.0f + cell * (static_cast<float>(j) + unit(hash(h, 3U))),
                                        -1.0f + margin, 1.0f - margin);
            const float r2 = ((sc - px) * (sc - px) + (tc - py) * (tc - py)) / (sigma * sigma);
            if (r2 > 9.0f) continue;
            const float t = unit(hash(h, 4U));  // colour temperature: blue-white to warm
            const Vec3 tint = mix(Vec3{0.75f, 0.85f, 1.0f}, Vec3{1.0f, 0.85f, 0.65f}, t);
            sum = sum + tint * (bright * std::exp(-0.5f * r2));
        }
    }
    return sum;
}

Vec3 moon(const Scene& s, Vec3 d, float cloud, float& near_out) {
    // Chord length approximates the angle for the small distances that matter here.
    const Vec3 diff = d - s.moon_dir;
    const float dist = std::sqrt(dot(diff, diff));
    near_out = std::exp(-dist / 0.12f);
    const float radius = 0.032f;
    const float edge = std::max(s.face_pix, 0.004f);
    Vec3 c = s.pal.moon_halo * (0.35f * std::exp(-dist / 0.05f) + 0.08f * std::exp(-dist / 0.3f));
    if (dist < radius + edge) {
        const float disc = smoothstep(radius + edge, radius - edge, dist);
        // Maria: low-contrast blotches on the disc.
        const float m = value_noise(diff.x * 90.0f, (diff.y + diff.z) * 90.0f, s.key ^ 0x3004U);
        c = c + s.pal.moon * (disc * (0.8f + 0.25f * m) * (1.0f - 0.75f * cloud));
    }
    return c;
}

// The colour of direction d, and in `cloud_room` how much a drifting cloud layer may cover it there.
// `layer` given: the clouds are drawn in (baked); none: they are left to the layer.
Vec3 shade(const Scene& s, const Image* layer, int face, float sc, float tc, float& cloud_room) {
    const Vec3 d = normalize(face_direction(face, sc, tc));
    cloud_room = 0.0f;
    const float glow = city_glow(s, d);

    Vec3 c;
    if (d.y >= 0.0f) {
        c = sky(s, d, glow);
        // Stars from about 12 to 20 degrees up (sines 0.21 to 0.34), fewer where the city glows.
        if (d.y > 0.2f)
            c = c + stars(s, face, sc, tc) * (smoothstep(0.21f, 0.34f, d.y) * (1.0f - 0.5f * glow));
        float moon_near = 0.0f;
        const float density = layer ? cloud_density(*layer, d) : 0.0f;
        cloud_room = cloud_fade(d);
        Vec3 m = moon(s, d, density, moon_near);
        c = c + m;
        if (density > 0.0f) c = clouds_over(s, d, c, density, glow, moon_near);
    }
    // The city: the street below the horizon, buildings up to 60 degrees (sine 0.866) above it.
    if (d.y < 0.87f) {
        const float az = std::atan2(d.x, -d.z);  // 0 towards -Z, increasing towards +X
        const float az_deg = (az < 0.0f ? az + 2.0f * kPi : az) / kDeg;
        float open_sky = 0.0f;
        c = city::city(s.city, d, std::min(az_deg, 359.999f), c, glow, open_sky);
        cloud_room *= open_sky;
    }
    return c;
}

Scene night_scene(std::uint64_t seed) {
    Scene s;
    s.key = hash(static_cast<std::uint32_t>(seed), hash(static_cast<std::uint32_t>(seed >> 32)));
    // The moon sits 35 degrees up towards -X, where the default camera sees the puddle reflect the sky.
    s.city.moon_az_deg = 260.0f + 20.0f * unit(hash(s.key, 5U));
    s.city.moon_el_deg = 35.0f;
    const float moon_az = s.city.moon_az_deg * kDeg, moon_el = s.city.moon_el_deg * kDeg;
    s.moon_dir = {std::cos(moon_el) * std::sin(moon_az), std::sin(moon_el),
                  -std::cos(moon_el) * std::cos(moon_az)};
    return s;
}

}  // namespace

CloudLight night_sky_cloud_light(std::uint64_t seed) {
    const Scene s = night_scene(seed);
    const auto rgb = [](Vec3 v) { return std::array<float, 3>{v.x, v.y, v.z}; };
    return {.base = rgb(s.pal.cloud_low),
            .top = rgb(s.pal.cloud_high),
            .moon_halo = rgb(s.pal.moon_halo * 0.6f),
            .moon_direction = rgb(s.moon_dir)};
}

CubeImages night_sky_cubemap(int face_size, std::uint64_t seed, SkyClouds clouds) {
    const int n = std::max(face_size, 1);
    Scene s = night_scene(seed);
    s.face_pix = 2.0f / static_cast<float>(n);
    const float phase1 = 2.0f * kPi * unit(hash(s.key, 6U)), phase2 = 2.0f * kPi * unit(hash(s.key, 7U));
    s.glow_c1 = std::cos(phase1);
    s.glow_s1 = std::sin(phase1);
    s.glow_c2 = std::cos(phase2);
    s.glow_s2 = std::sin(phase2);
    s.city = {.key = s.key,
              .pix_rad = 0.5f * kPi / static_cast<float>(n),
              .moon_az_deg = s.city.moon_az_deg,
              .moon_el_deg = s.city.moon_el_deg,
              .haze = s.pal.horizon,
              .band = s.pal.band};
    const Image layer = cloud_layer_image(seed);
    const Image* baked = clouds == SkyClouds::baked ? &layer : nullptr;

    CubeImages cube;
    cube.source = "procedural night sky";
    const auto render_face = [&](int face) {
        Image img = Image::make(n, n, PixelFormat::RGBA32F);
        for (int y = 0; y < n; ++y) {
            const float tc = 2.0f * (static_cast<float>(y) + 0.5f) / static_cast<float>(n) - 1.0f;
            for (int x = 0; x < n; ++x) {
                const float sc = 2.0f * (static_cast<float>(x) + 0.5f) / static_cast<float>(n) - 1.0f;
                float cloud_room = 0.0f;
                const Vec3 c = shade(s, baked, face, sc, tc, cloud_room);
                float* p = img.pixelf(x, y);
                p[0] = c.x;
                p[1] = c.y;
                p[2] = c.z;
                p[3] = baked ? 1.0f : cloud_room;
            }
        }
        cube.faces[static_cast<std::size_t>(face)] = std::move(img);
    };
    // Faces are independent, so they render in parallel: start-up time matters on a Raspberry Pi.
    {
        std::vector<std::jthread> workers;
        int face = 1;
        try {
            for (; face < 6; ++face) workers.emplace_back(render_face, face);
        } catch (const std::system_error&) {
            for (; face < 6; ++face) render_face(face);  // no threads to be had: finish on this one
        }
        render_face(0);
    }
    return cube;
}

}  // namespace puddle::assets
