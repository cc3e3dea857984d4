// libFuzzer target: arbitrary bytes through the text check, the lexer/parser and the AST
// builder, then every diagnostic rendered with its source line and caret. Any crash, sanitizer
// report or exception is a finding (the parser reports bad input as diagnostics, never throws).
#include "FuzzInput.h"
#include "voxc/syntax/Parser.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const voxc::SourceFile source = voxc::fuzz::sourceFromBytes(data, size);
    voxc::Diagnostics diagnostics;
    if (!voxc::reportIfNotText(source, diagnostics)) (void)voxc::parse(source, diagnostics);
    (void)voxc::renderAll(diagnostics.take(), source);
    return 0;
}
