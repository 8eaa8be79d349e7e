// The kms backend's choice of connector and mode (platform/kms_mode.hpp) on connectors filled in by hand:
// display.mode strings with and without a refresh, the text refused and the messages that name it, the
// preferred mode, and the messages for a card with nothing connected or without the connector asked for.
#include "platform/kms_mode.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "platform/drm_names.hpp"

namespace puddle::platform {
namespace {

drmModeModeInfo mode(int width, int height, int hz, bool preferred = false) {
    drmModeModeInfo m{};
    m.hdisplay = static_cast<std::uint16_t>(width);
    m.vdisplay = static_cast<std::uint16_t>(height);
    m.vrefresh = static_cast<std::uint32_t>(hz);
    m.type = DRM_MODE_TYPE_DRIVER | (preferred ? DRM_MODE_TYPE_PREFERRED : 0u);
    return m;
}

// A connector as drmModeGetConnector reports it; `modes` must outlive it.
drmModeConnector connector(std::uint32_t type, std::uint32_t type_id, bool connected,
                           std::vector<drmModeModeInfo>& modes) {
    drmModeConnector c{};
    c.connector_type = type;
    c.connector_type_id = type_id;
    c.connection = connected ? DRM_MODE_CONNECTED : DRM_MODE_DISCONNECTED;
    c.count_modes = static_cast<int>(modes.size());
    c.modes = modes.data();
    return c;
}

void expect_spec(std::string_view text, int width, int height, int refresh) {
    const auto spec = parse_mode(text);
    ASSERT_TRUE(spec.has_value()) << text;
    EXPECT_EQ(spec->width, width) << text;
    EXPECT_EQ(spec->height, height) << text;
    EXPECT_EQ(spec->refresh, refresh) << text;
}

TEST(KmsMode, ParsesASizeWithOrWithoutARefresh) {
    expect_spec("1920x1080", 1920, 1080, 0);
    expect_spec("1280x720@60", 1280, 720, 60);
    expect_spec("3840x2160@30", 3840, 2160, 30);
}

TEST(KmsMode, RefusesAnyOtherText) {
    for (const char* bad : {"", "1920", "1920x", "x1080", "1920X1080", "1920x1080@", "1920x1080@0", "0x1080",
                            "1920x0", "-1920x1080", "1920x1080@-60", " 1920x1080", "1920x1080 ",
                            "1920x1080@60Hz", "1920x1080x3", "1920*1080", "99999999999x1080"})
        EXPECT_FALSE(parse_mode(bad).has_value()) << "'" << bad << "'";
}

class KmsModeChoice : public ::testing::Test {
protected:
    // In the order a driver lists them: a duplicate, and the preferred mode after another of its size.
    std::vector<drmModeModeInfo> modes{mode(1280, 720, 60), mode(1920, 1080, 50), mode(1920, 1080, 60, true),
                                       mode(1920, 1080, 60), mode(1920, 1080, 30)};
    drmModeConnector hdmi = connector(DRM_MODE_CONNECTOR_HDMIA, 1, true, modes);
    const std::string card = "/dev/dri/card0";
};

TEST_F(KmsModeChoice, FindModePrefersThePreferredModeAmongThoseThatMatch) {
    EXPECT_EQ(find_mode(hdmi, std::nullopt), &modes[2]) << "no spec: the preferred mode";
    EXPECT_EQ(find_mode(hdmi, parse_mode("1920x1080")), &modes[2]) << "any refresh: the preferred one";
    EXPECT_EQ(find_mode(hdmi, parse_mode("1920x1080@50")), &modes[1]);
    EXPECT_EQ(find_mode(hdmi, parse_mode("1920x1080@30")), &modes[4]);
    EXPECT_EQ(find_mode(hdmi, parse_mode("1280x720")), &modes[0]) << "no preferred one matches: the first";
    EXPECT_EQ(find_mode(hdmi, parse_mode("800x600")), nullptr);
    EXPECT_EQ(find_mode(hdmi, parse_mode("1920x1080@75")), nullptr);
}

TEST_F(KmsModeChoice, WithoutAPreferredModeTheFirstIsUsed) {
    std::vector<drmModeModeInfo> plain{mode(1024, 768, 60), mode(800, 600, 60)};
    const drmModeConnector vga = connector(DRM_MODE_CONNECTOR_VGA, 1, true, plain);
    EXPECT_EQ(find_mode(vga, std::nullopt), &plain[0]);
}

TEST_F(KmsModeChoice, PickModeTakesDisplayModeThenSizeThenThePreferredMode) {
    auto picked = [&](const DisplayOptions& o) {
        auto m = pick_mode(card, hdmi, o);
        EXPECT_TRUE(m.ok()) << m.error().message;
        return m.ok() ? mode_name(*m) : std::string();
    };
    EXPECT_EQ(picked({.mode = "1920x1080@50"}), "1920x1080@50");
    EXPECT_EQ(picked({.size = {1280, 720}}), "1280x720@60");
    EXPECT_EQ(picked({.size = {1280, 720}, .mode = "1920x1080@30"}), "1920x1080@30") << "the mode wins";
    EXPECT_EQ(picked({.size = {640, 480}}), "1920x1080@60") << "no such size: the preferred mode";
    EXPECT_EQ(picked({}), "1920x1080@60");
}

TEST_F(KmsModeChoice, PickModeNamesTheTextOrTheModesThereAre) {
    const auto bad = pick_mode(card, hdmi, {.mode = "1920x1080p"});
    ASSERT_FALSE(bad.ok());
    EXPECT_EQ(bad.error().message, "kms: mode '1920x1080p' is not WIDTHxHEIGHT or WIDTHxHEIGHT@HZ");
    EXPECT_EQ(bad.error().code, ExitCode::Display);

    const auto absent = pick_mode(card, hdmi, {.mode = "800x600"});
    ASSERT_FALSE(absent.ok());
    EXPECT_EQ(absent.error().message,
              "kms: /dev/dri/card0: HDMI-A-1 has no mode 800x600; available: 1280x720@60, 1920x1080@50, "
              "1920x1080@60, 1920x1080@30")
        << "each mode once, in the driver's order";
    EXPECT_EQ(absent.error().code, ExitCode::Display);

    std::vector<drmModeModeInfo> none;
    const drmModeConnector empty = connector(DRM_MODE_CONNECTOR_HDMIA, 2, true, none);
    const auto no_modes = pick_mode(card, empty, {});
    ASSERT_FALSE(no_modes.ok());
    EXPECT_EQ(no_modes.error().message, "kms: /dev/dri/card0: HDMI-A-2 reports no modes");
}

class KmsConnectorChoice : public KmsModeChoice {
protected:
    std::vector<drmModeModeInfo> no_modes;
    drmModeConnector hdmi_off = connector(DRM_MODE_CONNECTOR_HDMIA, 2, false, modes);
    drmModeConnector dp = connector(DRM_MODE_CONNECTOR_DisplayPort, 1, true, modes);
    // Connected, but it reports no mode: it cannot show a picture either.
    drmModeConnector dsi = connector(DRM_MODE_CONNECTOR_DSI, 1, true, no_modes);
};

TEST_F(KmsConnectorChoice, TheFirstConnectedOneOrTheOneNamed) {
    const std::vector<const drmModeConnector*> all{&hdmi_off, &dsi, &dp, &hdmi};
    auto picked = [&](const std::string& wanted) {
        auto i = pick_connector(all, card, wanted);
        EXPECT_TRUE(i.ok()) << i.error().message;
        return i.ok() ? *i : all.size();
    };
    EXPECT_EQ(picked(""), 2u) << "DP-1: the first connected one with modes";
    EXPECT_EQ(picked("HDMI-A-1"), 3u);
    EXPECT_EQ(picked("DP-1"), 2u);
}

TEST_F(KmsConnectorChoice, ANamedConnectorThatIsDisconnectedOrAbsent) {
    const std::vector<const drmModeConnector*> all{&hdmi_off, &dsi, &dp};
    const auto off = pick_connector(all, card, "HDMI-A-2");
    ASSERT_FALSE(off.ok());
    EXPECT_EQ(off.error().message, "kms: /dev/dri/card0: connector HDMI-A-2 is not connected");
    EXPECT_EQ(off.error().code, ExitCode::Display);
    const auto modeless = pick_connector(all, card, "DSI-1");
    ASSERT_FALSE(modeless.ok());
    EXPECT_EQ(modeless.error().message, "kms: /dev/dri/card0: connector DSI-1 is not connected");
    const auto absent = pick_connector(all, card, "HDMI-A-1");
    ASSERT_FALSE(absent.ok());
    EXPECT_EQ(absent.error().message,
              "kms: /dev/dri/card0: no connector named HDMI-A-1; connectors: HDMI-A-2 (disconnected), DSI-1 "
              "(disconnected), DP-1 (connected)");
}

TEST_F(KmsConnectorChoice, NothingConnected) {
    const std::vector<const drmModeConnector*> dark{&hdmi_off, &dsi};
    const auto none = pick_connector(dark, card, "");
    ASSERT_FALSE(none.ok());
    EXPECT_EQ(none.error().message,
              "kms: /dev/dri/card0: no connected connector; connectors: HDMI-A-2 (disconnected), DSI-1 "
              "(disconnected)");
    EXPECT_EQ(none.error().code, ExitCode::Display);
    const auto empty = pick_connector({}, card, "");
    ASSERT_FALSE(empty.ok());
    EXPECT_EQ(empty.error().message, "kms: /dev/dri/card0: no connected connector; connectors: none");
}

}  // namespace
}  // namespace puddle::platform
