#include "voxc/core/Errors.h"
#include "voxc/render/Camera.h"

#include <gtest/gtest.h>
#include <string>

namespace voxc::rendering {
namespace {

const Bounds kBox{{0, 0, 0}, {95, 63, 95}};

std::string cameraError(const std::string& spec) {
    try {
        parseCamera(spec, kBox, 16.0f / 9.0f);
    } catch (const UserError& error) {
        return error.what();
    }
    return "";
}

std::string sizeError(const std::string& spec) {
    try {
        parseImageSize(spec);
    } catch (const UserError& error) {
        return error.what();
    }
    return "";
}

// A world point in normalised device coordinates.
glm::vec3 project(const Camera& camera, float aspect, glm::vec3 point) {
    const glm::vec4 clip = viewProjection(camera, aspect) * glm::vec4(point, 1.0f);
    return glm::vec3(clip) / clip.w;
}

TEST(Camera, PresetsFrameEveryCornerOfTheBox) {
    for (const char* preset : {"iso", "top", "side"})
        for (const float aspect : {16.0f / 9.0f, 1.0f, 0.5f}) {
            const Camera camera = parseCamera(preset, kBox, aspect);
            for (int corner = 0; corner < 8; ++corner) {
                const glm::vec3 p{corner & 1 ? kBox.max.x : kBox.min.x, corner & 2 ? kBox.max.y : kBox.min.y,
                                  corner & 4 ? kBox.max.z : kBox.min.z};
                const glm::vec3 ndc = project(camera, aspect, p);
                EXPECT_LE(std::abs(ndc.x), 1.0f) << preset << " corner " << corner;
                EXPECT_LE(std::abs(ndc.y), 1.0f) << preset << " corner " << corner;
                EXPECT_GT(ndc.z, 0.0f) << preset << " corner " << corner;
                EXPECT_LT(ndc.z, 1.0f) << preset << " corner " << corner;
            }
        }
}

TEST(Camera, TopLooksDownWithXToTheRightAndSideLooksAlongMinusZ) {
    const Camera top = parseCamera("top", kBox, 1.0f);
    EXPECT_GT(top.eye.y, kBox.max.y);
    EXPECT_GT(project(top, 1.0f, {95, 30, 47}).x, project(top, 1.0f, {0, 30, 47}).x);
    EXPECT_LT(project(top, 1.0f, {47, 30, 0}).y, project(top, 1.0f, {47, 30, 95}).y); // -z is up (Vulkan y down)
    const Camera side = parseCamera("side", kBox, 1.0f);
    EXPECT_GT(side.eye.z, kBox.max.z);
    EXPECT_LT(project(side, 1.0f, {47, 63, 47}).y, project(side, 1.0f, {47, 0, 47}).y); // y up
}

TEST(Camera, ExplicitEyeAndTarget) {
    const Camera camera = parseCamera("200,150.5,-20:48,20,48", kBox, 1.0f);
    EXPECT_EQ(camera.eye, glm::vec3(200, 150.5f, -20));
    EXPECT_EQ(camera.target, glm::vec3(48, 20, 48));
    EXPECT_NEAR(project(camera, 1.0f, camera.target).x, 0.0f, 1e-5f);
    // Straight down: y cannot be the picture's up.
    const Camera down = parseCamera("48,200,48:48,0,48", kBox, 1.0f);
    EXPECT_TRUE(std::isfinite(project(down, 1.0f, {0, 0, 0}).x));
}

TEST(Camera, BadSpellingsNameTheSpecAndTheForms) {
    for (const char* spec : {"", "front", "1,2:3,4,5", "1,2,3", "1,2,3:4,5,6:7", "a,b,c:1,2,3", "1,2,nan:0,0,0",
                             "1,2,3:4,5,6 "}) {
        const std::string message = cameraError(spec);
        EXPECT_NE(message.find(std::string("--camera ") + spec + ":"), std::string::npos) << message;
        EXPECT_NE(message.find("iso, top, side or X,Y,Z:TX,TY,TZ"), std::string::npos) << message;
    }
    EXPECT_NE(cameraError("5,5,5:5,5,5").find("the eye and the target are the same point"), std::string::npos);
}

TEST(ImageSize, WidthByHeight) {
    const ImageSize size = parseImageSize("1280x720");
    EXPECT_EQ(size.width, 1280u);
    EXPECT_EQ(size.height, 720u);
    EXPECT_EQ(parseImageSize("1x8192").height, 8192u);
    for (const char* spec : {"", "1280", "1280x", "x720", "0x720", "1280x0", "-5x5", "1280X720", "12.5x7", "8193x1",
                             "1280x720x3", "99999999999x1"}) {
        const std::string message = sizeError(spec);
        EXPECT_NE(message.find(std::string("--size ") + spec + ": expected WIDTHxHEIGHT"), std::string::npos) << message;
    }
}

} // namespace
} // namespace voxc::rendering
