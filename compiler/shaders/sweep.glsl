#version 450
// <<HEADER>>

// One sweep of a grammar: all rules of one window size. One invocation per anchor of the
// current phase; the windows of one phase never overlap, so every invocation owns its cells.
// The steps mirror the CPU interpreter: read the window, find the matching rules, choose one
// (voxc::chooseRule), then apply its transform.

#include "common.glsl"
#include "random.glsl"

layout(local_size_x = 8, local_size_y = 8, local_size_z = 1) in;

// <<RULE_TABLE>>

// voxc::chooseRule: the highest priority among the matched rules wins; equal priorities are
// drawn by weight in declaration order; the chosen rule then fires with its probability.
// Returns the index into the rule table above, or -1 when no rule fires.
int chooseRule(bool matched[RULE_COUNT], ivec3 anchorWorld) {
    bool found = false;
    int best = 0;
    for (int r = 0; r < RULE_COUNT; ++r) {
        if (!matched[r]) continue;
        best = found ? max(best, RULE_PRIORITY[r]) : RULE_PRIORITY[r];
        found = true;
    }
    if (!found) return -1;

    uint total = 0u;
    for (int r = 0; r < RULE_COUNT; ++r)
        if (matched[r] && RULE_PRIORITY[r] == best) total += RULE_WEIGHT_UNITS[r];

    uint seed = uint(push.gridSize.w);
    uint iteration = uint(push.chunkBase.w);
    uint sweep = uint(push.chunkCount.w);
    uint target = anchorHash(seed, iteration, sweep, anchorWorld, STREAM_RULE_CHOICE) % total;
    uint accumulated = 0u;
    int chosen = -1;
    for (int r = 0; r < RULE_COUNT; ++r) {
        if (!matched[r] || RULE_PRIORITY[r] != best) continue;
        accumulated += RULE_WEIGHT_UNITS[r];
        if (target < accumulated) {
            chosen = r;
            break;
        }
    }
    uint draw = anchorHash(seed, iteration, sweep, anchorWorld, STREAM_PROBABILITY) >> 8;
    return draw < RULE_PROBABILITY_UNITS[chosen] ? chosen : -1;
}

void main() {
    ivec3 id = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(id, push.anchorCount.xyz))) return;
    ivec3 anchor = push.anchorStart.xyz + id * push.anchorStep.xyz;
    ivec3 anchorWorld = push.gridOrigin.xyz + anchor;

    // <<LOAD_WINDOW>>

    // <<PASS_MASKS>>
    // <<MATCH_RULES>>

    int chosen = chooseRule(matched, anchorWorld);

    // <<APPLY_RULE>>
}
