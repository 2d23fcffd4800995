// The panel's size for the window and the display.
#include "app/panel_layout.hpp"

#include <gtest/gtest.h>

namespace {

TEST(PanelLayout, GrowsAndShrinksWithTheWindowAndTheTableKeepsMostOfIt) {
    const app::PanelLayout base = app::panel_layout(1280, 720);
    EXPECT_EQ(base.width, 300.0f);
    EXPECT_EQ(base.scale, 1.0f);
    const app::PanelLayout big = app::panel_layout(1920, 1080);
    EXPECT_EQ(big.width, 450.0f);
    EXPECT_EQ(big.scale, 1.5f);
    for (auto [w, h] : {std::pair{800, 600}, {640, 480}, {320, 240}, {2560, 600}, {700, 700}}) {
        const app::PanelLayout p = app::panel_layout(w, h);
        EXPECT_EQ(p.place, app::PanelPlace::right) << w << "x" << h;
        EXPECT_LE(p.width, 0.4f * static_cast<float>(w)) << w << "x" << h;
        EXPECT_GE(p.scale, 0.3f) << w << "x" << h;
        EXPECT_LE(p.scale * 300.0f, p.width * 1.1f + 0.5f) << "the text fits the panel";
    }
}

TEST(PanelLayout, ATallWindowHasThePanelBelowTheTableFullWidth) {
    const app::PanelLayout p = app::panel_layout(720, 1280);
    EXPECT_EQ(p.place, app::PanelPlace::below);
    EXPECT_EQ(p.width, 720.0f);
    EXPECT_EQ(p.height, 576.0f);  // 45 %
    EXPECT_EQ(p.scale, 1.0f);     // as a 1280×720 window's panel
    const app::ViewSize v = app::table_view(p, 720, 1280);
    EXPECT_EQ(v.width, 720);
    EXPECT_EQ(v.height, 704);
    // A phone upright, 390×844 CSS px, with a finger (1.5): a 17 px font, not squeezed.
    const app::PanelLayout phone = app::panel_layout(390, 844, 1.5f);
    EXPECT_EQ(phone.place, app::PanelPlace::below);
    EXPECT_EQ(phone.width, 390.0f);
    EXPECT_NEAR(phone.scale * 15.0f, 16.9f, 0.1f);
    EXPECT_EQ(app::table_view(phone, 390, 844).height, 844 - static_cast<int>(phone.height));
    for (auto [w, h] : {std::pair{320, 480}, {240, 1000}, {1000, 1001}, {1440, 2560}}) {
        const app::PanelLayout q = app::panel_layout(w, h, 2.0f);
        EXPECT_EQ(q.place, app::PanelPlace::below) << w << "x" << h;
        EXPECT_EQ(q.width, static_cast<float>(w));
        EXPECT_LE(q.scale * 300.0f, q.width * 1.1f + 0.5f) << "the text fits the panel";
        EXPECT_GE(app::table_view(q, w, h).height, h / 2) << "the table keeps more than half";
    }
}

TEST(PanelLayout, AWideWindowKeepsThePanelAtTheRightFullHeight) {
    const app::PanelLayout p = app::panel_layout(1280, 720);
    const app::ViewSize v = app::table_view(p, 1280, 720);
    EXPECT_EQ(p.height, 0.0f);
    EXPECT_EQ(v.width, 980);
    EXPECT_EQ(v.height, 720);
}

TEST(PanelLayout, HiDpiDisplaysScaleThePanel) {
    const app::PanelLayout p = app::panel_layout(2560, 1440, 2.0f);
    EXPECT_EQ(p.scale, 3.0f);  // 1.5 for the window, times 2 for the display
    EXPECT_EQ(p.width, 900.0f);
    EXPECT_EQ(app::panel_layout(2560, 1440, 2.0f).width, app::panel_layout(1280, 720).width * 3.0f);
    EXPECT_EQ(app::dpi_scale(nullptr, 0.0f), 1.0f);    // unknown
    EXPECT_EQ(app::dpi_scale(nullptr, 96.0f), 1.0f);   // a standard display
    EXPECT_EQ(app::dpi_scale(nullptr, 192.0f), 2.0f);  // HiDPI
    EXPECT_EQ(app::dpi_scale(nullptr, 140.0f), 1.5f);  // rounded to a quarter
    EXPECT_EQ(app::dpi_scale("1.25", 192.0f), 1.25f);  // the player's choice first
    EXPECT_EQ(app::dpi_scale("large", 192.0f), 2.0f);  // not a number: ignored
    EXPECT_EQ(app::dpi_scale("9", 0.0f), 1.0f);        // out of range: ignored
}

}  // namespace
