#include "voxc/codegen/Spirv.h"

#include "CompileCacheEntries.h"
#include "PackagedSpirv.h"

#include "voxc/core/Errors.h"

#include <algorithm>
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
    // Without friendly names: the validator's name mapper makes every repeated OpName unique by
    // probing suffixes one by one, quadratic in the number of equal names (minutes for a sweep
    // kernel with thousands of cells). Messages then name ids as %N.
    spvtools::ValidatorOptions validatorOptions;
    validatorOptions.SetFriendlyNames(false);
    if (tools.Validate(spirv.data(), spirv.size(), validatorOptions)) return std::nullopt;
    return messages.empty() ? std::string("invalid SPIR-V") : messages;
}

std::vector<uint32_t> spirvDescriptorBindings(const std::vector<uint32_t>& spirv) {
    // SPIR-V 1.3, 2.3-2.4: a 5-word header, then instructions whose first word holds the word
    // count (high half) and the opcode (low half). OpDecorate: target id, decoration, literal.
    constexpr uint32_t kOpDecorate = 71, kDecorationBinding = 33, kDecorationDescriptorSet = 34;
    std::vector<uint32_t> bindings;
    for (size_t at = 5; at < spirv.size();) {
        const uint32_t words = spirv[at] >> 16, opcode = spirv[at] & 0xffffu;
        VOXC_ASSERT(words > 0 && at + words <= spirv.size());
        if (opcode == kOpDecorate && words == 4) {
            if (spirv[at + 2] == kDecorationBinding) bindings.push_back(spirv[at + 3]);
            if (spirv[at + 2] == kDecorationDescriptorSet && spirv[at + 3] != 0)
                throw InternalError(fmt::format("a kernel declares descriptor set {}", spirv[at + 3]));
        }
        at += words;
    }
    std::sort(bindings.begin(), bindings.end());
    bindings.erase(std::unique(bindings.begin(), bindings.end()), bindings.end());
    return bindings;
}

namespace {

std::vector<uint32_t> compileUncached(std::string_view kernelName, const std::string& glsl,
                                      EShLanguage stage = EShLangCompute) {
    initGlslang();
    glslang::TShader shader(stage);
    const char* text = glsl.c_str();
    const std::string name(kernelName);
    const char* names = name.c_str();
    shader.setStringsWithLengthsAndNames(&text, nullptr, &names, 1);
    shader.setEnvInput(glslang::EShSourceGlsl, stage, glslang::EShClientVulkan, 100);
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
    glslang::GlslangToSpv(*program.getIntermediate(stage), spirv, &logger, &options);
    const std::string buildMessages = logger.getAllMessages();
    if (!buildMessages.empty()) fail(kernelName, "fails SPIR-V generation", buildMessages, glsl);
    if (std::optional<std::string> errors = spirvValidationErrors(spirv))
        fail(kernelName, "produces invalid SPIR-V", *errors, glsl);
    return spirv;
}

} // namespace

std::vector<uint32_t> compileComputeShader(std::string_view kernelName, const std::string& glsl) {
    if (std::optional<std::vector<uint32_t>> spirv = packagedSpirv(kernelName, glsl)) return std::move(*spirv);
    return cachedCompile(kernelName, glsl, [&] { return compileUncached(kernelName, glsl); });
}

std::vector<uint32_t> compileGraphicsShader(std::string_view name, const std::string& glsl, GraphicsStage stage) {
    return compileUncached(name, glsl, stage == GraphicsStage::Vertex ? EShLangVertex : EShLangFragment);
}

} // namespace voxc::codegen
