#include "assets/procedural.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <string>

#include "assets/cubemap_loader.hpp"
#include "assets/image.hpp"

namespace puddle::assets {
namespace {

enum Face { PX, NX, PY, NY, PZ, NZ };
enum class Edge { Left, Right, Top, Bottom };

// The twelve cube edges in GL face orientation: which edge of which face meets which, and whether the
// texels run in opposite directions along it. Checked against a real cubemap below.
struct Seam {
    Face a;
    Edge ea;
    Face b;
    Edge eb;
    bool reversed;
};
constexpr std::array<Seam, 12> kSeams{{
    {NX, Edge::Right, PZ, Edge::Left, false},
    {PZ, Edge::Right, PX, Edge::Left, false},
    {PX, Edge::Right, NZ, Edge::Left, false},
    {NZ, Edge::Right, NX, Edge::Left, false},
    {PY, Edge::Bottom, PZ, Edge::Top, false},
    {PY, Edge::Top, NZ, Edge::Top, true},
    {PY, Edge::Left, NX, Edge::Top, false},
    {PY, Edge::Right, PX, Edge::Top, true},
    {NY, Edge::Top, PZ, Edge::Bottom, false},
    {NY, Edge::Bottom, NZ, Edge::Bottom, true},
    {NY, Edge::Left, NX, Edge::Bottom, true},
    {NY, Edge::Right, PX, Edge::Bottom, false},
}};

const std::uint8_t* edge_texel(const Image& img, Edge e, int i) {
    const int n = img.width - 1;
    switch (e) {
        case Edge::Left:
            return img.pixel8(0, i);
        case Edge::Right:
            return img.pixel8(n, i);
        case Edge::Top:
            return img.pixel8(i, 0);
        default:
            return img.pixel8(i, n);
    }
}

// Mean absolute difference per channel between the texels on either side of a seam.
double seam_difference(const CubeImages& cube, const Seam& s, bool flip) {
    const Image& a = cube.faces[s.a];
    const Image& b = cube.faces[s.b];
    const int n = a.width;
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
        const std::uint8_t* pa = edge_texel(a, s.ea, i);
        const std::uint8_t* pb = edge_texel(b, s.eb, (s.reversed != flip) ? n - 1 - i : i);
        for (int c = 0; c < 3; ++c) sum += std::abs(int(pa[c]) - int(pb[c]));
    }
    return sum / (3.0 * n);
}

// Mean absolute difference per channel between a seam's edge texels on face a and their neighbours one
// texel further in: how much neighbouring texels differ there anyway.
double inner_difference(const CubeImages& cube, const Seam& s) {
    const Image& a = cube.faces[s.a];
    const int n = a.width;
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
        const std::uint8_t* edge = edge_texel(a, s.ea, i);
        const bool vertical = s.ea == Edge::Left || s.ea == Edge::Right;
        const int step = (s.ea == Edge::Left || s.ea == Edge::Top) ? 1 : -1;
        const std::uint8_t* in = vertical ? edge + 4 * step : edge + 4 * step * n;
        for (int c = 0; c < 3; ++c) sum += std::abs(int(edge[c]) - int(in[c]));
    }
    return sum / (3.0 * n);
}

double luma(const std::uint8_t* p) {
    return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
}

// Mean colour over a rectangle of one face.
std::array<double, 3> mean_rgb(const Image& img, int x0, int y0, int x1, int y1) {
    std::array<double, 3> sum{};
    for (int y = y0; y < y1; ++y) {
        for (int x = x0; x < x1; ++x) {
            for (int c = 0; c < 3; ++c) sum[static_cast<std::size_t>(c)] += img.pixel8(x, y)[c];
        }
    }
    const double count = double(x1 - x0) * double(y1 - y0);
    for (double& v : sum) v /= count;
    return sum;
}

int count_bright(const Image& img, int y0, int y1, int threshold) {
    int count = 0;
    for (int y = y0; y < y1; ++y) {
        for (int x = 0; x < img.width; ++x) {
            const std::uint8_t* p = img.pixel8(x, y);
            if (std::max({p[0], p[1], p[2]}) >= threshold) ++count;
        }
    }
    return count;
}

// Image row of a side face at a given elevation: tc = -tan(elevation), row 0 at tc = -1.
int side_row(int n, double elevation_deg) {
    const double tc = -std::tan(elevation_deg * 3.14159265358979 / 180.0);
    return static_cast<int>((tc + 1.0) * 0.5 * n);
}

// Mean linear radiance (luma) over the rows [y0, y1) of the four side faces.
double mean_radiance(const CubeImages& cube, int y0, int y1) {
    double sum = 0.0;
    for (Face f : {PX, NX, PZ, NZ})
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < cube.faces[f].width; ++x) {
                const float* p = cube.faces[f].pixelf(x, y);
                sum += 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
            }
    return sum / (4.0 * (y1 - y0) * cube.faces[PX].width);
}

// The sky is linear HDR (RGBA32F); the checks of what it looks like read it as the 8-bit sRGB a screen
// shows (clipped at white), the HDR checks read the floats.
class ProceduralNightSky : public ::testing::Test {
protected:
    static void SetUpTestSuite() {
        hdr_ = new CubeImages(night_sky_cubemap(256, 7));
        sky_ = new CubeImages;
        for (std::size_t f = 0; f < 6; ++f) sky_->faces[f] = to_srgb8(hdr_->faces[f]);
    }
    static void TearDownTestSuite() {
        delete sky_;
        delete hdr_;
        sky_ = hdr_ = nullptr;
    }
    static const CubeImages& sky() { return *sky_; }
    static const CubeImages& hdr() { return *hdr_; }

private:
    static inline CubeImages* sky_ = nullptr;
    static inline CubeImages* hdr_ = nullptr;
};

TEST_F(ProceduralNightSky, SameSeedGivesIdenticalBytesAndAnotherSeedDoesNot) {
    const CubeImages again = night_sky_cubemap(256, 7);
    const CubeImages other = night_sky_cubemap(256, 8);
    int differing_faces = 0;
    for (std::size_t f = 0; f < 6; ++f) {
        EXPECT_EQ(again.faces[f].data, hdr().faces[f].data) << cube_face_names[f];
        if (other.faces[f].data != hdr().faces[f].data) ++differing_faces;
    }
    EXPECT_EQ(differing_faces, 6);
}

TEST_F(ProceduralNightSky, FaceSizeIsHonoured) {
    for (int size : {1, 32, 100}) {
        const CubeImages cube = night_sky_cubemap(size, 3);
        EXPECT_EQ(cube.source, "procedural night sky");
        for (const Image& face : cube.faces) {
            EXPECT_EQ(face.width, size);
            EXPECT_EQ(face.height, size);
            EXPECT_EQ(face.format, PixelFormat::RGBA32F);
            EXPECT_EQ(face.data.size(), std::size_t(size) * std::size_t(size) * 16u);
            EXPECT_EQ(face.pixelf(size - 1, size - 1)[3], 1.0f);
        }
    }
}

TEST_F(ProceduralNightSky, ZenithIsDarkBlueAndTheHorizonGlowsWarm) {
    const int n = 256;
    const auto zenith = mean_rgb(sky().faces[PY], n / 2 - 4, n / 2 - 4, n / 2 + 4, n / 2 + 4);
    EXPECT_GT(zenith[2], zenith[0]) << "the zenith is blue";
    EXPECT_LT(zenith[2], 60.0);

    // Just above the tallest buildings (8 degrees), all around.
    const int row = side_row(n, 10.0);
    std::array<double, 3> glow{};
    for (Face f : {PX, NX, PZ, NZ}) {
        const auto m = mean_rgb(sky().faces[f], 0, row - 2, n, row + 2);
        for (std::size_t c = 0; c < 3; ++c) glow[c] += m[c] / 4.0;
    }
    const std::uint8_t zenith8[3] = {std::uint8_t(zenith[0]), std::uint8_t(zenith[1]),
                                     std::uint8_t(zenith[2])};
    const std::uint8_t glow8[3] = {std::uint8_t(glow[0]), std::uint8_t(glow[1]), std::uint8_t(glow[2])};
    EXPECT_GT(luma(glow8), 2.0 * luma(zenith8)) << "horizon glow is well brighter than the zenith";
    EXPECT_GT(glow[0], glow[2]) << "the glow is warm (sodium light pollution)";
}

// The steep sides of a drop's crater reflect the sky below the horizon: it is a lit street (well brighter
// than the open night sky), so impacts read as bright rings, not dark holes. Before the night city it was
// a black ground (sRGB 10, 10, 14), darker than the zenith.
TEST_F(ProceduralNightSky, BelowTheHorizonIsALitStreet) {
    const int n = 256;
    const double street = mean_radiance(hdr(), side_row(n, -5.0), side_row(n, -40.0));
    double zenith = 0.0;  // the open sky between the rooftops, straight up
    for (int y = n / 2 - 8; y < n / 2 + 8; ++y)
        for (int x = n / 2 - 8; x < n / 2 + 8; ++x) {
            const float* p = hdr().faces[PY].pixelf(x, y);
            zenith += (0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2]) / 256.0;
        }
    EXPECT_GT(street, 5.0 * zenith) << "the street is brighter than the open sky";
    EXPECT_GT(street, 0.03) << "a lit street, not a black ground";
    EXPECT_LT(street, 1.0) << "lit, not a light";
}

// HDR: windows, shop fronts, lamps and the moon are brighter than white, so they still glint after the
// tone curve; the background stays dark.
TEST_F(ProceduralNightSky, HighlightsGoPastWhite) {
    int past_white = 0, total = 0;
    float brightest = 0.0f;
    for (const Image& face : hdr().faces)
        for (int y = 0; y < face.height; ++y)
            for (int x = 0; x < face.width; ++x) {
                const float* p = face.pixelf(x, y);
                const float m = std::max({p[0], p[1], p[2]});
                brightest = std::max(brightest, m);
                past_white += m > 1.0f;
                ++total;
            }
    EXPECT_GT(brightest, 2.5f);
    EXPECT_GT(past_white, total / 200) << "lit windows are many";
    EXPECT_LT(past_white, total / 10) << "highlights are features, not the background";
}

TEST_F(ProceduralNightSky, HasStarsAboveAndLightsAlongTheSkyline) {
    const int n = 256;
    // Stars: bright texels on the top face, which is entirely above 35 degrees.
    EXPECT_GE(count_bright(sky().faces[PY], 0, n, 150), 40);

    // Windows and street lights: bright texels in the band from the horizon to 9 degrees up.
    int lights = 0;
    for (Face f : {PX, NX, PZ, NZ})
        lights += count_bright(sky().faces[f], side_row(n, 9.0), side_row(n, 0.0) + 1, 150);
    EXPECT_GE(lights, 150);

    // And the sky is not washed out: bright texels are features (stars, windows, shop fronts, lamps), not
    // the background. Towers of lit windows make them a few percent of the cube.
    int bright_total = 0;
    for (const Image& face : sky().faces) bright_total += count_bright(face, 0, n, 150);
    EXPECT_LT(bright_total, 6 * n * n / 10);
}

TEST_F(ProceduralNightSky, SeamsAreContinuous) {
    double right_total = 0.0, wrong_total = 0.0;
    for (const Seam& s : kSeams) {
        const double right = seam_difference(sky(), s, false);
        // Across a seam texels differ no more than neighbours inside a face do: where a window's edge runs
        // along the seam, neighbours inside differ as much.
        EXPECT_LT(right, 4.0 + 1.5 * inner_difference(sky(), s))
            << cube_face_names[s.a] << " meets " << cube_face_names[s.b];
        right_total += right;
        wrong_total += seam_difference(sky(), s, true);
    }
    // The check has teeth: the same edges joined the wrong way round differ clearly more.
    EXPECT_GT(wrong_total, 2.0 * right_total);
}

TEST(ProceduralSeamTable, MatchesARealCubemap) {
    const std::string folder = PUDDLE_SHARED_DIR "/assets/cubemap";
    if (!std::filesystem::exists(folder)) GTEST_SKIP() << "shared cubemap not found at " << folder;
    auto cube = load_cubemap_folder(folder);
    ASSERT_TRUE(cube.ok()) << cube.error().message;
    for (const Seam& s : kSeams) {
        const double right = seam_difference(*cube, s, false);
        const double wrong = seam_difference(*cube, s, true);
        EXPECT_LT(right, 12.0) << cube_face_names[s.a] << " meets " << cube_face_names[s.b];
        EXPECT_LT(right, wrong) << cube_face_names[s.a] << " meets " << cube_face_names[s.b];
    }
}

}  // namespace
}  // namespace puddle::assets
