#include "voxc/core/Errors.h"
#include "voxc/vulkan/Context.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <functional>
#include <filesystem>
#include <optional>

using namespace voxc;

namespace {

DeviceInfo fake(uint32_t index, DeviceType type, bool compute = true) {
    DeviceInfo d;
    d.index = index;
    d.name = std::string(deviceTypeName(type)) + "-device";
    d.type = type;
    d.hasCompute = compute;
    return d;
}

std::string userErrorText(const std::function<void()>& f) {
    try {
        f();
    } catch (const UserError& e) {
        return e.what();
    }
    return "(no UserError thrown)";
}

// Sets environment variables for one scope, restoring the previous values afterwards.
class ScopedEnv {
public:
    ScopedEnv(std::vector<std::pair<std::string, std::string>> values) {
        for (auto& [name, value] : values) {
            const char* old = std::getenv(name.c_str());
            saved_.push_back({name, old ? std::optional<std::string>(old) : std::nullopt});
            setenv(name.c_str(), value.c_str(), 1);
        }
    }
    ~ScopedEnv() {
        for (auto& [name, old] : saved_) {
            if (old) setenv(name.c_str(), old->c_str(), 1);
            else unsetenv(name.c_str());
        }
    }

private:
    std::vector<std::pair<std::string, std::optional<std::string>>> saved_;
};

bool hasGpu(const std::vector<DeviceInfo>& devices) {
    for (const DeviceInfo& d : devices)
        if (d.type != DeviceType::Cpu && d.hasCompute) return true;
    return false;
}

} // namespace

TEST(vulkan_Context, AutoPrefersDiscreteThenIntegratedThenCpu) {
    EXPECT_EQ(selectDevice({fake(0, DeviceType::Cpu), fake(1, DeviceType::Integrated), fake(2, DeviceType::Discrete)},
                           "auto"),
              2u);
    EXPECT_EQ(selectDevice({fake(0, DeviceType::Cpu), fake(1, DeviceType::Integrated)}, "auto"), 1u);
    EXPECT_EQ(selectDevice({fake(0, DeviceType::Cpu)}, "auto"), 0u);
    // A device without a compute queue is never chosen.
    EXPECT_EQ(selectDevice({fake(0, DeviceType::Discrete, false), fake(1, DeviceType::Cpu)}, "auto"), 1u);
}

TEST(vulkan_Context, NamedChoices) {
    const std::vector<DeviceInfo> mixed = {fake(0, DeviceType::Discrete), fake(1, DeviceType::Cpu)};
    EXPECT_EQ(selectDevice(mixed, "lavapipe"), 1u);
    EXPECT_EQ(selectDevice(mixed, "gpu"), 0u);
    EXPECT_EQ(selectDevice(mixed, "1"), 1u);
    EXPECT_EQ(selectDevice(mixed, "0"), 0u);
}

TEST(vulkan_Context, BadChoicesAreUserErrors) {
    const std::vector<DeviceInfo> cpuOnly = {fake(0, DeviceType::Cpu)};
    EXPECT_NE(userErrorText([&] { selectDevice(cpuOnly, "gpu"); }).find("no GPU Vulkan device found; available: 0: cpu-device (cpu)"),
              std::string::npos);
    EXPECT_NE(userErrorText([&] { selectDevice({fake(0, DeviceType::Discrete)}, "lavapipe"); }).find("no lavapipe"),
              std::string::npos);
    EXPECT_NE(userErrorText([&] { selectDevice(cpuOnly, "3"); }).find("index 3 is out of range"), std::string::npos);
    EXPECT_NE(userErrorText([&] { selectDevice(cpuOnly, "99999999999999"); }).find("out of range"), std::string::npos);
    EXPECT_NE(userErrorText([&] { selectDevice(cpuOnly, "fastest"); }).find("unknown device 'fastest'"),
              std::string::npos);
    EXPECT_NE(userErrorText([&] { selectDevice(cpuOnly, "-1"); }).find("unknown device"), std::string::npos);
    EXPECT_NE(userErrorText([&] { selectDevice({}, "auto"); }).find("no Vulkan device found"), std::string::npos);
}

TEST(vulkan_Context, ListsTheLavapipeDevice) {
    const std::vector<DeviceInfo> devices = VulkanContext::listDevices();
    ASSERT_FALSE(devices.empty());
    bool cpu = false;
    for (const DeviceInfo& d : devices) cpu = cpu || (d.type == DeviceType::Cpu && d.hasCompute);
    EXPECT_TRUE(cpu) << formatDeviceList(devices);
    const std::string listing = formatDeviceList(devices);
    EXPECT_NE(listing.find("0: "), std::string::npos);
    EXPECT_NE(listing.find("Vulkan 1."), std::string::npos) << listing;
}

TEST(vulkan_Context, LavapipeAndIndexChoicesOpenADevice) {
    VulkanContext lavapipe(ContextOptions{.device = "lavapipe"});
    EXPECT_EQ(lavapipe.device().type, DeviceType::Cpu);
    VulkanContext first(ContextOptions{.device = "0"});
    EXPECT_EQ(first.device().index, 0u);
    const size_t count = VulkanContext::listDevices().size();
    EXPECT_NE(userErrorText([&] { VulkanContext c(ContextOptions{.device = std::to_string(count)}); }).find("out of range"),
              std::string::npos);
}

TEST(vulkan_Context, GpuChoiceWithoutGpuIsUserError) {
    if (hasGpu(VulkanContext::listDevices())) GTEST_SKIP() << "this machine has a GPU";
    const std::string text = userErrorText([] { VulkanContext c(ContextOptions{.device = "gpu"}); });
    EXPECT_NE(text.find("no GPU Vulkan device found; available: "), std::string::npos) << text;
    EXPECT_NE(text.find("(cpu)"), std::string::npos) << text;
}

TEST(vulkan_Context, MissingLoaderIsUserError) {
    ContextOptions options;
    options.loaderLibrary = "libvoxc-no-such-vulkan-loader.so.1";
    const std::string text = userErrorText([&] { VulkanContext c(options); });
    EXPECT_NE(text.find("cannot load the Vulkan loader 'libvoxc-no-such-vulkan-loader.so.1'"), std::string::npos)
        << text;
    EXPECT_NE(userErrorText([&] { VulkanContext::listDevices(options.loaderLibrary); }).find("cannot load"),
              std::string::npos);
}

TEST(vulkan_Context, NoDriverIsUserError) {
    // Both spellings: VK_DRIVER_FILES (loader >= 1.3.207) and the older VK_ICD_FILENAMES.
    ScopedEnv env({{"VK_DRIVER_FILES", "/nonexistent/voxc_icd.json"}, {"VK_ICD_FILENAMES", "/nonexistent/voxc_icd.json"}});
    const std::string text = userErrorText([] { VulkanContext c; });
    EXPECT_TRUE(text.find("no Vulkan driver found") != std::string::npos ||
                text.find("no Vulkan device found") != std::string::npos)
        << text;
}

TEST(vulkan_Context, MissingValidationLayerIsUserError) {
    // VK_LAYER_PATH replaces the explicit-layer search path, so an empty folder hides the layer.
    const std::filesystem::path empty = std::filesystem::temp_directory_path() / "voxc_no_layers";
    std::filesystem::create_directories(empty);
    ScopedEnv env({{"VK_LAYER_PATH", empty.string()}});
    ContextOptions options;
    options.validation = true;
    const std::string text = userErrorText([&] { VulkanContext c(options); });
    EXPECT_NE(text.find("VK_LAYER_KHRONOS_validation is not installed"), std::string::npos) << text;
}

TEST(vulkan_Context, ValidationContextStartsClean) {
    ContextOptions options;
    options.validation = true;
    VulkanContext context(options);
    EXPECT_TRUE(context.validationEnabled());
    for (const ValidationMessage& m : context.validationMessages()) ADD_FAILURE() << m.text;
}
