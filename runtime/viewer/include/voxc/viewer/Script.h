#pragma once
// `voxc view --script FILE`: actions that drive the viewer without a person, one per line, `#`
// starts a comment (docs/viewer.md, "Scripts"):
//   camera iso|top|side|X,Y,Z:TX,TY,TZ   the view, spelled as `voxc render --camera`
//   carve PX PY | add PX PY              the brush where the ray through window pixel (PX, PY) meets the surface
//   carve-ray X,Y,Z DX,DY,DZ | add-ray   ... where the ray from X,Y,Z along DX,DY,DZ does
//   set NAME VALUE                       a slider: a parameter (Session.h's Parameter::name), radius or softness
//   undo | redo | reload                 reload: re-check and re-run now, as a saved file would
//   save-edits PATH                      the edits as `voxc run --edits` reads them
//   wait SECONDS                         keep drawing (and watching the file)
//   wait-change SECONDS                  until the file changes and is reloaded; an error after SECONDS
//   wait-refined SECONDS                 until a coarse preview's full solve replaces it; an error after SECONDS
//   screenshot PATH                      the 3D view as PNG (no panel), as `voxc render` draws it
//   screenshot-window PATH               the whole window as shown, panel included
// A malformed line is a located error: E0008 unknown action, E0006 wrong number of operands,
// E0010 an operand that is not a number or point, E0007 a value out of range.
#include "voxc/syntax/Diagnostics.h"
#include "voxc/syntax/SourceFile.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

namespace voxc::viewer {

struct Action {
    enum class Kind : uint8_t { Camera, Carve, Add, Set, Undo, Redo, Reload, SaveEdits, Wait, WaitChange,
                                WaitRefined, Screenshot, ScreenshotWindow };
    Kind kind = Kind::Wait;
    SourceLoc loc = {};       // the action's word
    std::string text = {};    // Camera: the spec; Set: the name; SaveEdits, Screenshot, ScreenshotWindow: the path
    double value = 0.0; // Set: the value; Wait, WaitChange, WaitRefined: seconds
    bool alongRay = false;       // Carve, Add: a ray (origin, direction) rather than a pixel
    glm::vec2 pixel{0.0f};
    glm::vec3 origin{0.0f}, direction{0.0f};
};

inline constexpr double kMaxScriptWaitSeconds = 3600.0;

std::vector<Action> parseScript(const SourceFile& source, Diagnostics& diagnostics);

} // namespace voxc::viewer
