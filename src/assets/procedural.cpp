#include "assets/procedural.hpp"

#include <algorithm>
#include <cmath>
#include <system_error>
#include <thread>
#include <vector>

namespace puddle::assets {
namespace {

// Everything is shaded in linear light and encoded to sRGB once, at the end.
struct Vec3 {
    float x = 0, y = 0, z = 0;
};
Vec3 operator+(Vec3 a, Vec3 b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
Vec3 operator-(Vec3 a, Vec3 b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
Vec3 operator*(Vec3 a, float s) {
    return {a.x * s, a.y * s, a.z * s};
}
Vec3 mix(Vec3 a, Vec3 b, float t) {
    return a + (b - a) * t;
}
float dot(Vec3 a, Vec3 b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
Vec3 normalize(Vec3 a) {
    return a * (1.0f / std::sqrt(dot(a, a)));
}

constexpr float kPi = 3.14159265f;
constexpr float kDeg = kPi / 180.0f;

float clamp01(float v) {
    return std::clamp(v, 0.0f, 1.0f);
}
float smoothstep(float e0, float e1, float x) {
    const float t = clamp01((x - e0) / (e1 - e0));
    return t * t * (3.0f - 2.0f * t);
}
float srgb_to_linear(float c) {
    c /= 255.0f;
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}
Vec3 srgb(float r, float g, float b) {
    return {srgb_to_linear(r), srgb_to_linear(g), srgb_to_linear(b)};
}

// Integer hashing (Wellons' lowbias32): the same sky on every machine, no rand() state.
std::uint32_t hash(std::uint32_t x) {
    x ^= x >> 16;
    x *= 0x7feb352dU;
    x ^= x >> 15;
    x *= 0x846ca68bU;
    x ^= x >> 16;
    return x;
}
std::uint32_t hash(std::uint32_t a, std::uint32_t b) {
    return hash(a ^ hash(b + 0x9e3779b9U));
}
std::uint32_t hash(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
    return hash(a, hash(b, c));
}
std::uint32_t as_u32(int i) {
    return static_cast<std::uint32_t>(i);
}
float unit(std::uint32_t h) {
    return static_cast<float>(h >> 8) * (1.0f / 16777216.0f);
}

float value_noise(float x, float y, std::uint32_t key) {
    const float fx = std::floor(x), fy = std::floor(y);
    const int ix = static_cast<int>(fx), iy = static_cast<int>(fy);
    float tx = x - fx, ty = y - fy;
    tx = tx * tx * (3.0f - 2.0f * tx);
    ty = ty * ty * (3.0f - 2.0f * ty);
    // One hash per lattice corner (noise is the hot spot): mix the coordinates, then hash once.
    const std::uint32_t hx = as_u32(ix) * 0x8da6b343U, hy = as_u32(iy) * 0xd8163841U;
    const float a = unit(hash(hx ^ hy ^ key));
    const float b = unit(hash((hx + 0x8da6b343U) ^ hy ^ key));
    const float c = unit(hash(hx ^ (hy + 0xd8163841U) ^ key));
    const float d = unit(hash((hx + 0x8da6b343U) ^ (hy + 0xd8163841U) ^ key));
    return a + (b - a) * tx + (c - a) * ty + (a - b - c + d) * tx * ty;
}

// Four octaves, each rotated so the lattice does not show; result roughly in [0, 1].
float fbm(float x, float y, std::uint32_t key) {
    float sum = 0.0f, amp = 0.5f;
    for (int o = 0; o < 4; ++o) {
        sum += amp * value_noise(x, y, key + as_u32(o));
        const float nx = 1.6f * x + 1.2f * y, ny = -1.2f * x + 1.6f * y;
        x = nx + 17.0f;
        y = ny - 5.0f;
        amp *= 0.5f;
    }
    return sum / 0.9375f;
}

// Coverage of a pixel of width w centred at x by the interval [lo, hi]: antialiased edges.
float cover(float x, float lo, float hi, float w) {
    return clamp01(std::min(x - lo, hi - x) / w + 0.5f);
}

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
    Vec3 ground = srgb(10, 10, 14);
    Vec3 cloud_high = srgb(34, 30, 44);
    Vec3 cloud_low = srgb(96, 66, 52);  // cloud bases lit from below by the city
    Vec3 near_building = srgb(9, 9, 13);
    Vec3 moon = Vec3{1.25f, 1.2f, 1.05f};
    Vec3 moon_halo = srgb(120, 130, 160);
};

// Everything that depends on the seed or the face size, computed once per cubemap.
struct Scene {
    std::uint32_t key = 0;
    float pix_deg = 0.35f;   // about one texel, in degrees, for antialiasing
    float face_pix = 0.01f;  // one texel in face coordinates
    Vec3 moon_dir;
    float glow_c1 = 0, glow_s1 = 0, glow_c2 = 0, glow_s2 = 0;  // cos and sin of the glow's phases
    Palette pal;
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

// Clouds on a flat layer above the viewer, so they shrink with perspective towards the horizon.
float cloud_density(const Scene& s, Vec3 d) {
    if (d.y < 0.01f) return 0.0f;
    const float k = 1.0f / (d.y + 0.1f);
    const float n = fbm(d.x * k * 1.1f + 3.0f, d.z * k * 1.1f - 7.0f, s.key ^ 0xc10dU);
    return smoothstep(0.45f, 0.75f, n) * smoothstep(0.01f, 0.12f, d.y) * 0.85f;
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
            if (unit(h) > 0.3f) continue;  // a city sky: few stars
            const float b = unit(hash(h, 1U));
            const float bright = 0.08f + 1.8f * b * b * b * b;
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

// One slot of a skyline layer: a building (or a gap) occupying [left, right] of the slot, in degrees.
struct Building {
    bool present = false;
    float left = 0, right = 0, height = 0;
    std::uint32_t id = 0;
};

Building building_in_slot(const Scene& s, int slot, std::uint32_t layer, float slot_deg, float min_h,
                          float max_h, float tower_chance, float gap_chance) {
    const std::uint32_t h = hash(as_u32(slot), layer, s.key);
    Building b;
    b.id = h;
    b.present = unit(hash(h, 11U)) >= gap_chance;
    b.left = slot_deg * 0.12f * unit(hash(h, 12U));
    b.right = slot_deg * (1.0f - 0.12f * unit(hash(h, 13U)));
    const float r = unit(hash(h, 14U));
    b.height = min_h + (max_h - min_h) * r * r;
    if (unit(hash(h, 15U)) < tower_chance) b.height = max_h + (8.0f - max_h) * unit(hash(h, 16U));
    return b;
}

struct Windows {
    float col_deg, row_deg, w_deg, h_deg, lit_min, lit_max, gain;
};

// Lit windows on a building face: a grid of small rectangles, some lit in warm or cool colours.
Vec3 windows(const Scene& s, const Building& b, float x_deg, float el_deg, const Windows& w) {
    const float inner = x_deg - b.left - 0.25f * w.col_deg;
    if (inner < 0.0f || x_deg > b.right - 0.25f * w.col_deg || el_deg > b.height - 0.45f * w.row_deg)
        return {};
    const int col = static_cast<int>(inner / w.col_deg);
    const int row = static_cast<int>(el_deg / w.row_deg);
    const float cx = (static_cast<float>(col) + 0.5f) * w.col_deg;
    const float cy = (static_cast<float>(row) + 0.5f) * w.row_deg;
    const float m = cover(inner, cx - 0.5f * w.w_deg, cx + 0.5f * w.w_deg, s.pix_deg) *
                    cover(el_deg, cy - 0.5f * w.h_deg, cy + 0.5f * w.h_deg, s.pix_deg);
    if (m <= 0.0f) return {};
    const std::uint32_t h = hash(b.id, as_u32(col), as_u32(row));
    const float lit_share = w.lit_min + (w.lit_max - w.lit_min) * unit(hash(b.id, 21U));
    if (unit(h) > lit_share) return {};
    const float kind = unit(hash(h, 22U));
    const Vec3 colour = kind < 0.6f    ? Vec3{1.0f, 0.72f, 0.36f}  // incandescent
                        : kind < 0.85f ? Vec3{1.0f, 0.9f, 0.7f}    // warm white
                                       : Vec3{0.65f, 0.8f, 1.0f};  // screens, LEDs
    return colour * (m * w.gain * (0.35f + 0.65f * unit(hash(h, 23U))));
}

Vec3 skyline(const Scene& s, Vec3 c, float az_deg, float el_deg, float glow) {
    // Far layer: narrow, lower, hazy blocks with few windows; it fills the gaps of the near layer.
    {
        constexpr float slot = 360.0f / 240.0f;
        const int i = static_cast<int>(az_deg / slot);
        const Building b = building_in_slot(s, i, 1U, slot, 0.8f, 3.6f, 0.05f, 0.1f);
        if (b.present && el_deg < b.height + s.pix_deg) {
            const float x = az_deg - static_cast<float>(i) * slot;
            const float m =
                cover(x, b.left, b.right, s.pix_deg) * clamp01((b.height - el_deg) / s.pix_deg + 0.5f);
            Vec3 col = mix(s.pal.near_building, s.pal.horizon * glow, 0.3f);
            col = col + windows(s, b, x, el_deg, {0.45f, 0.42f, 0.22f, 0.2f, 0.05f, 0.2f, 0.55f});
            c = mix(c, col, m);
        }
    }
    // Near layer: wider, darker buildings, towers up to 8 degrees, many lit windows.
    {
        constexpr float slot = 360.0f / 120.0f;
        const int i = static_cast<int>(az_deg / slot);
        const Building b = building_in_slot(s, i, 2U, slot, 1.0f, 5.5f, 0.1f, 0.22f);
        if (b.present && el_deg < b.height + 0.5f) {
            const float x = az_deg - static_cast<float>(i) * slot;
            const float m =
                cover(x, b.left, b.right, s.pix_deg) * clamp01((b.height - el_deg) / s.pix_deg + 0.5f);
            Vec3 col = mix(s.pal.near_building, s.pal.horizon * glow, 0.06f);
            col = col + windows(s, b, x, el_deg, {0.62f, 0.55f, 0.32f, 0.3f, 0.12f, 0.5f, 1.0f});
            c = mix(c, col, m);
            // Red aviation light on top of towers.
            if (b.height > 5.5f) {
                const float dx = x - 0.5f * (b.left + b.right), dy = el_deg - (b.height + 0.15f);
                const float r = std::max(0.12f, 0.6f * s.pix_deg);
                c = c + Vec3{2.0f, 0.12f, 0.06f} * std::exp(-(dx * dx + dy * dy) / (r * r));
            }
        }
    }
    return c;
}

// Street lights along the horizon: a hot core and a wide halo, sodium orange or LED white.
Vec3 street_lights(const Scene& s, float az_deg, float el_deg) {
    constexpr int slots = 44;
    constexpr float slot = 360.0f / slots;
    const int i0 = static_cast<int>(az_deg / slot);
    Vec3 sum;
    for (int k = i0 - 1; k <= i0 + 1; ++k) {
        const int i = (k + slots) % slots;
        const std::uint32_t h = hash(as_u32(i), 3U, s.key);
        if (unit(h) > 0.7f) continue;
        const float laz = (static_cast<float>(k) + 0.15f + 0.7f * unit(hash(h, 31U))) * slot;
        const float lel = 0.25f + 0.9f * unit(hash(h, 32U));
        const float dx = az_deg - laz, dy = el_deg - lel;
        const float d2 = dx * dx + dy * dy;
        if (d2 > 16.0f) continue;
        const float fade = (1.0f - d2 / 16.0f) * (1.0f - d2 / 16.0f);  // no visible rim where the halo stops
        const bool sodium = unit(hash(h, 33U)) < 0.7f;
        const Vec3 colour = sodium ? Vec3{1.0f, 0.5f, 0.14f} : Vec3{0.8f, 0.88f, 1.0f};
        const float core_r = std::max(0.12f, 0.7f * s.pix_deg);
        const float gain = 0.6f + 0.6f * unit(hash(h, 34U));
        sum =
            sum + colour * (gain * (4.0f * std::exp(-d2 / (core_r * core_r)) + 0.5f * std::exp(-d2 / 0.35f) +
                                    0.12f * fade * std::exp(-std::sqrt(d2) / 1.3f)));
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

Vec3 shade(const Scene& s, int face, float sc, float tc) {
    const Vec3 d = normalize(face_direction(face, sc, tc));
    const float glow = city_glow(s, d);

    Vec3 c;
    if (d.y >= 0.0f) {
        c = sky(s, d, glow);
        // Stars from about 12 to 20 degrees up (sines 0.21 to 0.34), fewer where the city glows.
        if (d.y > 0.2f)
            c = c + stars(s, face, sc, tc) * (smoothstep(0.21f, 0.34f, d.y) * (1.0f - 0.5f * glow));
        float moon_near = 0.0f;
        const float density = cloud_density(s, d);
        Vec3 m = moon(s, d, density, moon_near);
        c = c + m;
        if (density > 0.0f) c = clouds_over(s, d, c, density, glow, moon_near);
    } else {
        // Ground, lifted by haze just below the horizon (1.2 degrees is about 0.021 in sine).
        c = s.pal.ground + s.pal.horizon * (0.3f * glow * std::exp(d.y / 0.021f));
    }
    // The skyline and street lights live between 5 degrees down and 9 up (sines -0.087, 0.156).
    if (d.y < 0.156f && d.y > -0.087f) {
        const float el_deg = std::asin(d.y) / kDeg;
        const float az = std::atan2(d.x, -d.z);  // 0 towards -Z, increasing towards +X
        const float az_deg = (az < 0.0f ? az + 2.0f * kPi : az) / kDeg;
        if (el_deg >= -0.5f) c = skyline(s, c, az_deg, std::max(el_deg, 0.0f), glow);
        c = c + street_lights(s, az_deg, el_deg);
    }
    return c;
}

// sRGB encoding through a table indexed by linear value; fine enough near black, where the curve is steep.
class SrgbEncoder {
public:
    SrgbEncoder() : table_(kSize + 1) {
        for (int i = 0; i <= kSize; ++i) {
            const float l = static_cast<float>(i) / kSize;
            const float e = l <= 0.0031308f ? 12.92f * l : 1.055f * std::pow(l, 1.0f / 2.4f) - 0.055f;
            table_[static_cast<std::size_t>(i)] = e * 255.0f;
        }
    }
    // dither in [-0.5, 0.5) hides banding in the dark gradients.
    std::uint8_t operator()(float linear, float dither) const {
        const float v = table_[static_cast<std::size_t>(clamp01(linear) * kSize + 0.5f)] + dither;
        return static_cast<std::uint8_t>(std::clamp(v + 0.5f, 0.0f, 255.0f));
    }

private:
    static constexpr int kSize = 16384;
    std::vector<float> table_;
};

}  // namespace

CubeImages night_sky_cubemap(int face_size, std::uint64_t seed) {
    const int n = std::max(face_size, 1);
    Scene s;
    s.key = hash(static_cast<std::uint32_t>(seed), hash(static_cast<std::uint32_t>(seed >> 32)));
    s.face_pix = 2.0f / static_cast<float>(n);
    s.pix_deg = 90.0f / static_cast<float>(n);
    // The moon sits 35 degrees up towards -X, where the default camera sees the puddle reflect the sky.
    const float moon_az = (-100.0f + 20.0f * unit(hash(s.key, 5U))) * kDeg;
    const float moon_el = 35.0f * kDeg;
    s.moon_dir = {std::cos(moon_el) * std::sin(moon_az), std::sin(moon_el),
                  -std::cos(moon_el) * std::cos(moon_az)};
    const float phase1 = 2.0f * kPi * unit(hash(s.key, 6U)), phase2 = 2.0f * kPi * unit(hash(s.key, 7U));
    s.glow_c1 = std::cos(phase1);
    s.glow_s1 = std::sin(phase1);
    s.glow_c2 = std::cos(phase2);
    s.glow_s2 = std::sin(phase2);

    const SrgbEncoder encode;
    CubeImages cube;
    cube.source = "procedural night sky";
    const auto render_face = [&](int face) {
        Image img = Image::make(n, n, PixelFormat::RGBA8);
        for (int y = 0; y < n; ++y) {
            const float tc = 2.0f * (static_cast<float>(y) + 0.5f) / static_cast<float>(n) - 1.0f;
            for (int x = 0; x < n; ++x) {
                const float sc = 2.0f * (static_cast<float>(x) + 0.5f) / static_cast<float>(n) - 1.0f;
                const Vec3 c = shade(s, face, sc, tc);
                const std::uint32_t h = hash(as_u32(x), as_u32(y), s.key + as_u32(face));
                std::uint8_t* p = img.pixel8(x, y);
                p[0] = encode(c.x, unit(h) - 0.5f);
                p[1] = encode(c.y, unit(hash(h)) - 0.5f);
                p[2] = encode(c.z, unit(hash(h + 1U)) - 0.5f);
                p[3] = 255;
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
