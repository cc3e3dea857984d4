#include "voxc/codegen/Spirv.h"

#include "voxc/core/Errors.h"

#include <fmt/format.h>
#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>
#include <mutex>
#include <spirv-tools/libspirv.hpp>

namespace voxc::codegen {

namespace {

// glslang needs one process-wide initialisation; it is never finalised because kernels may
// be compiled until exit.
void initGlslang() {
    static std::once_flag once;
    std::call_once(once, [] { glslang::InitializeProcess(); });
}

std::string numbered(const std::string& source) {
    std::string out;
    int line = 1;
    size_t pos = 0;
    while (pos < source.size()) {
        size_t end = source.find('\n', pos);
        if (end == std::string::npos) end = source.size();
        out += fmt::format("{:5} | {}\n", line++, std::string_view(source).substr(pos, end - pos));
        pos = end + 1;
    }
    return out;
}

[[noreturn]] void fail(std::string_view kernelName, std::string_view what, std::string_view log,
                       const std::string& glsl) {
    throw InternalError(
        fmt::format("generated kernel '{}' {}:\n{}\nsource:\n{}", kernelName, what, log, numbered(glsl)));
}

} // namespace

std::optional<std::string> spirvValidationErrors(const std::vector<uint32_t>& spirv) {
    spvtools::SpirvTools tools(SPV_ENV_VULKAN_1_1);
    std::string messages;
    tools.SetMessageConsumer(
        [&](spv_message_level_t, const char*, const spv_position_t& position, const char* message) {
            messages += fmt::format("word {}: {}\n", position.index, message);
        });
    if (tools.Validate(spirv)) return std::nullopt;
    return messages.empty() ? std::string("invalid SPIR-V") : messages;
}

std::vector<uint32_t> compileComputeShader(std::string_view kernelName, const std::string& glsl) {
    initGlslang();
    glslang::TShader shader(EShLangCompute);
    const char* text = glsl.c_str();
    const std::string name(kernelName);
    const char* names = name.c_str();
    shader.setStringsWithLengthsAndNames(&text, nullptr, &names, 1);
    shader.setEnvInput(glslang::EShSourceGlsl, EShLangCompute, glslang::EShClientVulkan, 100);
    shader.setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_1);
    shader.setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_3);
    const EShMessages messages = EShMessages(EShMsgSpvRules | EShMsgVulkanRules);
    if (!shader.parse(GetDefaultResources(), 450, false, messages))
        fail(kernelName, "does not compile", shader.getInfoLog(), glsl);

    glslang::TProgram program;
    program.addShader(&shader);
    if (!program.link(messages)) fail(kernelName, "does not link", program.getInfoLog(), glsl);

    std::vector<uint32_t> spirv;
    spv::SpvBuildLogger logger;
    glslang::SpvOptions options;
    options.validate = false; // validated below, with the messages kept
    glslang::GlslangToSpv(*program.getIntermediate(EShLangCompute), spirv, &logger, &options);
    const std::string buildMessages = logger.getAllMessages();
    if (!buildMessages.empty()) fail(kernelName, "fails SPIR-V generation", buildMessages, glsl);
    if (std::optional<std::string> errors = spirvValidationErrors(spirv))
        fail(kernelName, "produces invalid SPIR-V", *errors, glsl);
    return spirv;
}

} // namespace voxc::codegen
