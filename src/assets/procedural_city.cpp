#include "assets/procedural_city.hpp"

#include <algorithm>
#include <cmath>

namespace puddle::assets::city {

using namespace shading;

namespace {

const Vec3 kBuilding = srgb(9, 9, 13);
constexpr float kEye = 1.0f;  // eye height above the street, the unit of the city's sizes

// One slot of a skyline layer: a building (or a gap) occupying [left, right] of the slot, in degrees.
struct Building {
    bool present = false;
    float left = 0, right = 0, height = 0;
    std::uint32_t id = 0;
};

// One layer of the far skyline: block heights in degrees, and the chances of a tower and of a gap.
struct SkylineLayer {
    float min_h, max_h;
    float tower_chance, gap_chance;
};

Building building_in_slot(const CityView& v, int slot, std::uint32_t layer, float slot_deg,
                          const SkylineLayer& l) {
    const float min_h = l.min_h, max_h = l.max_h, tower_chance = l.tower_chance, gap_chance = l.gap_chance;
    const std::uint32_t h = hash(as_u32(slot), layer, v.key);
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

// A window's colour: incandescent, warm white, or the blue of screens and LEDs.
Vec3 window_colour(std::uint32_t h) {
    const float kind = unit(hash(h, 22U));
    return kind < 0.6f    ? Vec3{1.0f, 0.72f, 0.36f}
           : kind < 0.85f ? Vec3{1.0f, 0.9f, 0.7f}
                          : Vec3{0.65f, 0.8f, 1.0f};
}

// A far building's window grid, in degrees of view, and how many are lit.
struct Windows {
    float col_deg, row_deg;  // grid pitch
    float w_deg, h_deg;      // one window
    float lit_min, lit_max;  // the lit fraction ranges between these over the buildings
    float gain;              // brightness of a lit window
};

// Lit windows on a far building: a grid of small rectangles in degrees, some lit.
Vec3 far_windows(const CityView& v, const Building& b, float x_deg, float el_deg, const Windows& w) {
    const float pix_deg = v.pix_rad / kDeg;
    const float inner = x_deg - b.left - 0.25f * w.col_deg;
    if (inner < 0.0f || x_deg > b.right - 0.25f * w.col_deg || el_deg > b.height - 0.45f * w.row_deg)
        return {};
    const int col = static_cast<int>(inner / w.col_deg);
    const int row = static_cast<int>(el_deg / w.row_deg);
    const float cx = (static_cast<float>(col) + 0.5f) * w.col_deg;
    const float cy = (static_cast<float>(row) + 0.5f) * w.row_deg;
    const float m = cover(inner, cx - 0.5f * w.w_deg, cx + 0.5f * w.w_deg, pix_deg) *
                    cover(el_deg, cy - 0.5f * w.h_deg, cy + 0.5f * w.h_deg, pix_deg);
    if (m <= 0.0f) return {};
    const std::uint32_t h = hash(b.id, as_u32(col), as_u32(row));
    // As on the near facades, whole floors are busy or asleep.
    const float floor_busy = unit(hash(b.id, 62U, as_u32(row)));
    const float lit_share = (w.lit_min + (w.lit_max - w.lit_min) * unit(hash(b.id, 21U))) *
                            (0.2f + 1.6f * floor_busy * floor_busy);
    if (unit(h) > lit_share) return {};
    return window_colour(h) * (m * w.gain * (0.35f + 0.65f * unit(hash(h, 23U))));
}

// The far skyline: two layers of blocks up to 8 degrees high on the horizon, behind the near buildings.
// sky_left: the share of `c` (the sky) left showing between the blocks.
Vec3 far_skyline(const CityView& v, Vec3 c, float az_deg, float el_deg, float glow, float& sky_left) {
    const float pix_deg = v.pix_rad / kDeg;
    sky_left = 1.0f;
    // Far layer: narrow, lower, hazy blocks with few windows; it fills the gaps of the middle layer.
    {
        constexpr float slot = 360.0f / 240.0f;
        const int i = static_cast<int>(az_deg / slot);
        const Building b = building_in_slot(
            v, i, 1U, slot, {.min_h = 0.8f, .max_h = 3.6f, .tower_chance = 0.05f, .gap_chance = 0.1f});
        if (b.present && el_deg < b.height + pix_deg) {
            const float x = az_deg - static_cast<float>(i) * slot;
            const float m =
                cover(x, b.left, b.right, pix_deg) * clamp01((b.height - el_deg) / pix_deg + 0.5f);
            Vec3 col = mix(kBuilding, v.haze * glow, 0.3f);
            col = col + far_windows(v, b, x, el_deg,
                                    {.col_deg = 0.45f,
                                     .row_deg = 0.42f,
                                     .w_deg = 0.22f,
                                     .h_deg = 0.2f,
                                     .lit_min = 0.05f,
                                     .lit_max = 0.2f,
                                     .gain = 1.2f});
            c = mix(c, col, m);
            sky_left *= 1.0f - m;
        }
    }
    // Middle layer: wider, darker blocks, towers up to 8 degrees, many lit windows.
    {
        constexpr float slot = 360.0f / 120.0f;
        const int i = static_cast<int>(az_deg / slot);
        const Building b = building_in_slot(
            v, i, 2U, slot, {.min_h = 1.0f, .max_h = 5.5f, .tower_chance = 0.1f, .gap_chance = 0.22f});
        if (b.present && el_deg < b.height + 0.5f) {
            const float x = az_deg - static_cast<float>(i) * slot;
            const float m =
                cover(x, b.left, b.right, pix_deg) * clamp01((b.height - el_deg) / pix_deg + 0.5f);
            Vec3 col = mix(kBuilding, v.haze * glow, 0.12f);
            col = col + far_windows(v, b, x, el_deg,
                                    {.col_deg = 0.62f,
                                     .row_deg = 0.55f,
                                     .w_deg = 0.32f,
                                     .h_deg = 0.3f,
                                     .lit_min = 0.12f,
                                     .lit_max = 0.5f,
                                     .gain = 2.0f});
            c = mix(c, col, m);
            sky_left *= 1.0f - m;
            // Red aviation light on top of towers.
            if (b.height > 5.5f) {
                const float dx = x - 0.5f * (b.left + b.right), dy = el_deg - (b.height + 0.15f);
                const float r = std::max(0.12f, 0.6f * pix_deg);
                c = c + Vec3{4.0f, 0.25f, 0.12f} * std::exp(-(dx * dx + dy * dy) / (r * r));
            }
        }
    }
    return c;
}

// Street lights along the far horizon, in the gaps between near buildings: a hot core and a halo.
Vec3 far_street_lights(const CityView& v, float az_deg, float el_deg) {
    constexpr int slots = 44;
    constexpr float slot = 360.0f / slots;
    const float pix_deg = v.pix_rad / kDeg;
    const int i0 = static_cast<int>(az_deg / slot);
    Vec3 sum;
    for (int k = i0 - 1; k <= i0 + 1; ++k) {
        const int i = (k + slots) % slots;
        const std::uint32_t h = hash(as_u32(i), 3U, v.key);
        if (unit(h) > 0.7f) continue;
        const float laz = (static_cast<float>(k) + 0.15f + 0.7f * unit(hash(h, 31U))) * slot;
        const float lel = 0.25f + 0.9f * unit(hash(h, 32U));
        const float dx = az_deg - laz, dy = el_deg - lel;
        const float d2 = dx * dx + dy * dy;
        if (d2 > 16.0f) continue;
        const float fade = (1.0f - d2 / 16.0f) * (1.0f - d2 / 16.0f);  // no visible rim where the halo stops
        const bool sodium = unit(hash(h, 33U)) < 0.7f;
        const Vec3 colour = sodium ? Vec3{1.0f, 0.5f, 0.14f} : Vec3{0.8f, 0.88f, 1.0f};
        const float core_r = std::max(0.12f, 0.7f * pix_deg);
        const float gain = 0.6f + 0.6f * unit(hash(h, 34U));
        sum =
            sum + colour * (gain * (8.0f * std::exp(-d2 / (core_r * core_r)) + 0.5f * std::exp(-d2 / 0.35f) +
                                    0.12f * fade * std::exp(-std::sqrt(d2) / 1.3f)));
    }
    return sum;
}

// A near building: a facade `distance` units away (drawn as an arc around the viewer, so its floors stay
// level), spanning [left, right] degrees of its slot, its roof `top_rad` up. No two look alike: the roof
// line, the window grid, how the floors are lit and whether a sign hangs on it all come from its hash.
enum class Roof { Flat, Setback, Spire, Notch, Stepped };

struct Facade {
    bool present = false;
    float left = 0, right = 0, distance = 10, top_rad = 0.3f;
    std::uint32_t id = 0;
    Roof roof = Roof::Flat;
    // Window grid, units: a cell of col_w x row_h, the window win_w x win_h in it (ribbon windows nearly
    // fill the cell's width).
    float col_w = 1.5f, row_h = 1.8f, win_w = 0.8f, win_h = 0.9f;
    Vec3 warm, cool;  // the building's two window colours: most of its lit windows are `warm`
    float cool_share = 0.2f;
};

constexpr int kNearSlots = 28;
constexpr float kNearSlotDeg = 360.0f / kNearSlots;

Facade facade_in_slot(const CityView& v, int slot) {
    const std::uint32_t h = hash(as_u32((slot + kNearSlots) % kNearSlots), 5U, v.key);
    Facade f;
    f.id = h;
    f.present = unit(hash(h, 41U)) > 0.08f;  // some slots are side streets: the far city shows through
    f.left = kNearSlotDeg * 0.06f * unit(hash(h, 42U));
    f.right = kNearSlotDeg * (1.0f - 0.06f * unit(hash(h, 43U)));
    f.distance = 14.0f + 20.0f * unit(hash(h, 44U));
    const float r = unit(hash(h, 45U));
    float top_deg = 10.0f + 34.0f * r * r;
    if (unit(hash(h, 46U)) < 0.12f) top_deg = 48.0f + 12.0f * unit(hash(h, 47U));  // a tower
    // The moon shows in a gap of the rooftops, framed by tall buildings on either side: the slot in front
    // of it stays 10 degrees below it, its four neighbours each way rise well above it.
    const float mid = (static_cast<float>(slot) + 0.5f) * kNearSlotDeg;
    float off = std::fabs(mid - v.moon_az_deg);
    off = std::min(off, 360.0f - off) / kNearSlotDeg;
    const bool before_moon = off < 0.5f;
    if (before_moon)
        top_deg = std::min(top_deg, v.moon_el_deg - 10.0f);
    else if (off < 4.5f)
        top_deg = std::max(top_deg, v.moon_el_deg + 8.0f + 14.0f * r);
    f.top_rad = top_deg * kDeg;

    const float roof = unit(hash(h, 48U));
    f.roof = before_moon    ? (roof < 0.5f ? Roof::Flat : Roof::Notch)
             : roof < 0.3f  ? Roof::Flat
             : roof < 0.55f ? Roof::Setback
             : roof < 0.7f  ? Roof::Spire
             : roof < 0.85f ? Roof::Stepped
                            : Roof::Notch;
    const bool ribbon = unit(hash(h, 54U)) < 0.2f;  // offices: bands of glass along each floor
    f.col_w = 1.1f + 1.3f * unit(hash(h, 55U));
    f.row_h = 1.6f + 0.6f * unit(hash(h, 56U));
    f.win_w = f.col_w * (ribbon ? 0.94f : 0.35f + 0.4f * unit(hash(h, 57U)));
    f.win_h = f.row_h * (0.42f + 0.3f * unit(hash(h, 58U)));
    // Homes burn incandescent and warm white; offices fluorescent white, a few the green of old tubes.
    const bool office = ribbon || unit(hash(h, 59U)) < 0.25f;
    f.warm = office ? Vec3{0.85f, 0.93f, 1.0f} : Vec3{1.0f, 0.7f, 0.34f};
    f.cool = office ? Vec3{0.75f, 1.0f, 0.8f} : Vec3{0.6f, 0.75f, 1.0f};
    f.cool_share = office ? 0.15f : 0.1f + 0.25f * unit(hash(h, 60U));
    return f;
}

// The roof's elevation (radians) at x degrees into the facade's slot: the silhouette against the sky.
float roof_rad(const Facade& f, float x) {
    const float t = (x - f.left) / std::max(f.right - f.left, 1e-3f);  // 0 to 1 across the facade
    const float inset = 0.15f + 0.2f * unit(hash(f.id, 70U));
    switch (f.roof) {
        case Roof::Setback:  // the upper floors step back from both sides
            return (t < inset || t > 1.0f - inset) ? f.top_rad * (0.72f + 0.12f * unit(hash(f.id, 71U)))
                                                   : f.top_rad;
        case Roof::Spire: {  // a mast on the roof's middle
            const float half = 0.18f / std::max(f.right - f.left, 1e-3f);
            const float mast =
                std::fabs(t - 0.5f) < half ? (4.0f + 6.0f * unit(hash(f.id, 72U))) * kDeg : 0.0f;
            return f.top_rad + mast;
        }
        case Roof::Stepped: {  // three tiers, highest on one side
            const bool right_high = unit(hash(f.id, 73U)) < 0.5f;
            const float u = right_high ? t : 1.0f - t;
            return f.top_rad * (u < 0.33f ? 0.78f : u < 0.66f ? 0.9f : 1.0f);
        }
        case Roof::Notch:  // two towers on one base
            return std::fabs(t - 0.5f) < 0.12f ? f.top_rad * 0.8f : f.top_rad;
        case Roof::Flat:
        default: {  // plant rooms and water tanks break the line
            const int bay = static_cast<int>(t * 9.0f);
            const std::uint32_t b = hash(f.id, 74U, as_u32(bay));
            return f.top_rad + (unit(b) < 0.3f ? (0.4f + 1.0f * unit(hash(b, 75U))) * kDeg : 0.0f);
        }
    }
}

// A sign's light: the colours of neon and LED, brighter than any window.
Vec3 sign_colour(std::uint32_t h) {
    static const Vec3 colours[] = {{1.0f, 0.12f, 0.55f}, {0.1f, 0.85f, 1.0f},  {1.0f, 0.1f, 0.06f},
                                   {0.2f, 1.0f, 0.35f},  {1.0f, 0.55f, 0.08f}, {0.3f, 0.35f, 1.0f}};
    return colours[hash(h, 80U) % 6U];
}

// Signs on the facade at u units from its left edge, `above` the street: a vertical blade sign on some
// buildings, a fascia over some shop fronts, each with letters (blocks of its colour) and a halo that
// lights the wall around it.
Vec3 facade_signs(const Facade& f, float u, float above, float width, float du, float dh) {
    Vec3 c;
    const std::uint32_t hb = hash(f.id, 81U);
    if (unit(hb) < 0.45f) {  // a blade sign
        const float w = 0.7f + 0.4f * unit(hash(hb, 1U)), ht = 3.0f + 4.0f * unit(hash(hb, 2U));
        const float x0 = width * (0.1f + 0.8f * unit(hash(hb, 3U))), y0 = 2.6f + 1.2f * unit(hash(hb, 4U));
        const float dx = std::max({x0 - u, u - (x0 + w), 0.0f}),
                    dy = std::max({y0 - above, above - (y0 + ht), 0.0f});
        const Vec3 colour = sign_colour(hb) * (4.0f + 3.0f * unit(hash(hb, 5U)));
        const float inside = cover(u, x0, x0 + w, du) * cover(above, y0, y0 + ht, dh);
        if (inside > 0.0f) {
            // One letter per 0.6 units down the sign; a letter is a block with a dark gap around it.
            const float letter = std::floor((above - y0) / 0.6f);
            const float in_letter =
                cover(std::fmod(above - y0, 0.6f), 0.08f, 0.52f, dh) * cover(u - x0, 0.12f, w - 0.12f, du);
            const float lit = unit(hash(hb, as_u32(static_cast<int>(letter)))) < 0.85f ? 1.0f : 0.15f;
            c = c + colour * (inside * (0.12f + 0.88f * in_letter * lit));
        }
        const float d2 = dx * dx + dy * dy;
        if (d2 < 9.0f) c = c + colour * (0.05f * std::exp(-std::sqrt(d2) / 0.6f) * (1.0f - d2 / 9.0f));
    }
    const std::uint32_t hf = hash(f.id, 82U);
    if (unit(hf) < 0.35f && above > 1.3f && above < 2.6f) {  // a lit fascia over the shop front
        const float x0 = width * 0.15f * unit(hash(hf, 1U)), x1 = width * (0.55f + 0.4f * unit(hash(hf, 2U)));
        const Vec3 colour = sign_colour(hf) * (2.5f + 2.0f * unit(hash(hf, 3U)));
        c = c + colour * (cover(u, x0, x1, du) * cover(above, 1.6f, 2.05f, dh));
        const float dx = std::max({x0 - u, u - x1, 0.0f}), dy = std::max(1.6f - above, above - 2.05f);
        if (dy > 0.0f) c = c + colour * (0.04f * std::exp(-(dy + dx) / 0.25f));
    }
    return c;
}

// How a lit window's light falls across it, 0 to 1, at (x, y) in its cell (fractions, y up): brightest
// under the ceiling's lights, dimmer toward the sill; split into panes by dark mullions; in some a blind
// drawn part-way down, in some a dark shape (furniture, a person) against the light. No two windows of a
// floor look alike, so the grid does not read as a pattern.
float window_interior(const Facade& f, std::uint32_t wh, float cell_x, float cell_y, float du, float dh) {
    const float gap_w = 0.5f * (f.col_w - f.win_w), gap_h = 0.45f * (f.row_h - f.win_h);
    const float x = (cell_x * f.col_w - gap_w) / f.win_w, y = (cell_y * f.row_h - gap_h) / f.win_h;
    const float ax = du / f.win_w, ay = dh / f.win_h;  // a texel, in window fractions
    float light = 0.45f + 0.55f * clamp01(y);
    // Panes a unit or so wide (ribbon windows have many); a mullion is a tenth of a unit.
    const float panes = std::max(1.0f, std::round(f.win_w / 1.0f));
    if (panes > 1.0f) {
        const float px = x * panes - std::floor(x * panes);
        const float bar = 0.05f * panes / f.win_w;
        light *= 1.0f - 0.85f * (1.0f - cover(px, bar, 1.0f - bar, ax * panes));
    }
    const std::uint32_t b = hash(wh, 25U);
    if (unit(b) < 0.3f) {  // a blind: the light through it softer and warmer-looking, dimmer
        const float edge = 0.35f + 0.55f * unit(hash(b, 1U));
        light *= 1.0f - 0.6f * clamp01((y - edge) / ay + 0.5f);
    }
    const std::uint32_t s = hash(wh, 26U);
    if (unit(s) < 0.22f) {  // a dark shape low in the window
        const float x0 = 0.1f + 0.6f * unit(hash(s, 1U)), w = 0.15f + 0.25f * unit(hash(s, 2U));
        const float top = 0.25f + 0.35f * unit(hash(s, 3U));
        light *= 1.0f - 0.75f * cover(x, x0, x0 + w, ax) * clamp01((top - y) / ay + 0.5f);
    }
    return light;
}

// The facade at horizontal position u and height h (units; the street is at h = -kEye); u_local is u
// from the facade's left edge, `width` its width. du, dh: a texel's size there, for antialiasing. A unit is
// the eye's height (about 1.6 m), so a storey (row_h) of 1.6 to 2.2 units is 2.6 to 3.5 m.
Vec3 facade_colour(const CityView& v, const Facade& f, float u, float u_local, float width, float h, float du,
                   float dh, float glow) {
    const float above = h + kEye;  // height above the street
    // Walls catch a little of the street's light low down and of the glowing sky high up; some are paler.
    const float pale = 0.6f + 0.8f * unit(hash(f.id, 50U));
    Vec3 c = kBuilding * pale + v.haze * (glow * (0.04f + 0.12f * std::exp(-above / 3.0f)));
    c = c + facade_signs(f, u_local, above, width, du, dh);
    // The ground floor: a lit shop front (most buildings) under a dark fascia, mullions every 2 units.
    if (above < 2.2f) {
        if (unit(hash(f.id, 51U)) < 0.75f) {
            const float band = cover(above, 0.1f, 1.5f, dh);
            const float mullion = 1.0f - 0.8f * cover(std::fmod(u + 1000.0f, 2.0f), 0.0f, 0.15f, du);
            const Vec3 light =
                unit(hash(f.id, 52U)) < 0.7f ? Vec3{1.0f, 0.75f, 0.45f} : Vec3{0.8f, 0.9f, 1.0f};
            c = c + light * ((1.5f + 2.0f * unit(hash(f.id, 53U))) * band * mullion);
        }
        return c;
    }
    // Storeys of windows in the building's own grid.
    const float fu = u / f.col_w, fh = (above - 2.2f) / f.row_h;
    const float cu = std::floor(fu), ch = std::floor(fh);
    const float gap_w = 0.5f * (f.col_w - f.win_w), gap_h = 0.45f * (f.row_h - f.win_h);
    const float m = cover((fu - cu) * f.col_w, gap_w, gap_w + f.win_w, du) *
                    cover((fh - ch) * f.row_h, gap_h, gap_h + f.win_h, dh);
    if (m <= 0.0f) return c;
    const int floor_i = static_cast<int>(ch);
    const std::uint32_t wh = hash(f.id, as_u32(static_cast<int>(cu)), as_u32(floor_i));
    // Lit windows come in runs: some floors are busy, some asleep, and along a floor a flat or an office
    // of four to seven windows is lit or dark together.
    const float floor_busy = unit(hash(f.id, 62U, as_u32(floor_i)));
    const int run = static_cast<int>(std::floor(cu / (4.0f + 3.0f * unit(hash(f.id, 63U)))));
    const float run_lit = unit(hash(f.id, as_u32(run), as_u32(floor_i) + 7919U));
    const float lit_share = (0.2f + 0.45f * unit(hash(f.id, 21U))) * (0.3f + 1.4f * floor_busy);
    if (0.6f * run_lit + 0.4f * unit(wh) > lit_share + 0.25f)
        return c + Vec3{0.012f, 0.014f, 0.024f} * m;  // dark glass: a little sky in it
    const float gain =
        unit(hash(wh, 23U)) < 0.25f ? 0.3f : 1.2f + 2.5f * unit(hash(wh, 24U));  // some curtained
    const Vec3 colour =
        (unit(hash(wh, 22U)) < f.cool_share ? f.cool : f.warm) * (0.8f + 0.4f * unit(hash(wh, 28U)));
    return c + colour * (m * gain * window_interior(f, wh, fu - cu, fh - ch, du, dh));
}

// The street below the horizon where no facade stands: wet paving lit by lamp pools and the city's glow,
// shining where it reflects the glow at grazing angles, fading into the haze far away.
Vec3 street(const CityView& v, Vec3 d, float glow) {
    const float down = std::max(-d.y, 1e-4f);
    const float t = kEye / down;
    const float px = d.x * t, pz = d.z * t;
    const float r = std::sqrt(px * px + pz * pz);
    // Paving: rows of 0.3 x 0.2 setts, every other row offset by half; detail fades where a texel covers
    // several setts.
    const float texel = v.pix_rad * t / down;  // a texel's footprint on the street, along the view
    const float detail = smoothstep(0.2f, 0.05f, texel);
    float paving = 1.0f;
    if (detail > 0.0f) {
        const float row = std::floor(pz / 0.2f);
        const float shifted = px / 0.3f + 0.5f * std::fmod(std::fabs(row), 2.0f);
        const float col = std::floor(shifted);
        const float joint =
            cover((shifted - col) * 0.3f, 0.02f, 0.28f, texel) * cover(pz - row * 0.2f, 0.02f, 0.18f, texel);
        const float stone =
            0.7f + 0.3f * unit(hash(as_u32(static_cast<int>(col)), as_u32(static_cast<int>(row)), v.key));
        paving = 1.0f + (stone * (0.45f + 0.55f * joint) - 1.0f) * detail;
    }
    // Lamps on a jittered 10-unit grid; each texel sums the pools of its own cell and the eight around it.
    Vec3 light = Vec3{1.0f, 0.62f, 0.35f} * (0.1f * glow);  // the city's general glow, bounced
    constexpr float cell = 10.0f;
    const int cx = static_cast<int>(std::floor(px / cell)), cz = static_cast<int>(std::floor(pz / cell));
    for (int j = cz - 1; j <= cz + 1; ++j)
        for (int i = cx - 1; i <= cx + 1; ++i) {
            const std::uint32_t h = hash(as_u32(i), as_u32(j), v.key ^ 0x1a3bU);
            if (unit(h) > 0.65f) continue;
            const float lx = (static_cast<float>(i) + 0.2f + 0.6f * unit(hash(h, 61U))) * cell;
            const float lz = (static_cast<float>(j) + 0.2f + 0.6f * unit(hash(h, 62U))) * cell;
            const float q = ((px - lx) * (px - lx) + (pz - lz) * (pz - lz)) / (3.0f * 3.0f);
            const Vec3 colour =
                unit(hash(h, 63U)) < 0.7f ? Vec3{1.0f, 0.55f, 0.2f} : Vec3{0.75f, 0.85f, 1.0f};
            light = light + colour * (1.6f / ((1.0f + q) * (1.0f + q)));
        }
    Vec3 c = light * (0.5f * paving);
    // Wet: at grazing angles the street mirrors the glowing band over the city (Schlick-like rise).
    const float grazing = 1.0f - down;
    const float g2 = grazing * grazing;
    c = c + v.band * (glow * 0.35f * g2 * g2 * grazing);
    // Far away the street disappears into the haze.
    return mix(c, v.haze * (0.8f * glow) + v.band * (0.12f * glow), smoothstep(40.0f, 200.0f, r));
}

}  // namespace

Vec3 city(const CityView& v, Vec3 d, float az_deg, Vec3 sky, float glow, float& open_sky) {
    open_sky = 0.0f;
    const float el = std::asin(std::clamp(d.y, -1.0f, 1.0f));
    const float horiz = std::sqrt(d.x * d.x + d.z * d.z);
    // A texel spans more azimuth towards the poles.
    const float pix_az_deg = v.pix_rad / std::max(horiz, 0.05f) / kDeg;

    // The near facade of this azimuth's slot, if the direction meets it.
    const int slot = std::min(static_cast<int>(az_deg / kNearSlotDeg), kNearSlots - 1);
    const Facade f = facade_in_slot(v, slot);
    float m = 0.0f;
    Vec3 near;
    const float x = az_deg - static_cast<float>(slot) * kNearSlotDeg;
    const float roof = f.present ? roof_rad(f, x) : 0.0f;
    if (f.present && el < roof + v.pix_rad) {
        m = cover(x, f.left, f.right, pix_az_deg) * clamp01((roof - el) / v.pix_rad + 0.5f);
        const float h = f.distance * std::tan(el);
        if (m > 0.0f && h > -kEye) {
            const float cos_el = std::cos(el);
            const float du = v.pix_rad * f.distance / std::max(horiz, 0.05f);
            const float dh = v.pix_rad * f.distance / (cos_el * cos_el);
            const float to_units = kDeg * f.distance;
            near = facade_colour(v, f, az_deg * to_units, (x - f.left) * to_units,
                                 (f.right - f.left) * to_units, h, du, dh, glow);
        } else if (h <= -kEye) {
            m = 0.0f;  // below the facade's foot: the street in front of it
        }
    }
    if (m >= 1.0f) return near;

    Vec3 behind;
    if (d.y >= 0.0f) {
        behind = sky;
        open_sky = 1.0f - m;
        const float el_deg = el / kDeg;
        if (el_deg < 9.0f) {
            float sky_left = 1.0f;
            behind =
                far_skyline(v, behind, az_deg, el_deg, glow, sky_left) + far_street_lights(v, az_deg, el_deg);
            open_sky *= sky_left;
        }
    } else {
        behind = street(v, d, glow);
    }
    return mix(behind, near, m);
}

}  // namespace puddle::assets::city
