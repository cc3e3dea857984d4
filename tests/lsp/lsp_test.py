#!/usr/bin/env python3
"""Speaks the Language Server Protocol to `voxc lsp` over pipes, as an editor does.

Usage: lsp_test.py VOXC SOURCE_DIR. Checks initialize, that didOpen publishes exactly the
diagnostics `voxc check --diagnostics-format json` reports (codes, ranges, severities, the rule
file's on the rule file's URI), didChange, hover, completion and definition, that a hover during a
running check answers at once (checks run on a thread of their own), robustness against malformed
messages, and shutdown/exit. Prints "N passed, N failed" last.
"""
import json
import os
import subprocess
import sys
import tempfile
import threading
import time

from lsp_client import Client, check, finish, uri

voxc, src = sys.argv[1], sys.argv[2]


def check_json(path):
    """What `voxc check --diagnostics-format json` says, as LSP would: uri -> [(code, severity, range)]."""
    run = subprocess.run([voxc, "check", "-q", path, "--diagnostics-format", "json"], capture_output=True, text=True)
    expected = {}
    severities = {"error": 1, "warning": 2, "note": 3}
    for line in run.stderr.splitlines():
        d = json.loads(line)
        if "summary" in d:
            continue  # the closing summary
        r = d["range"]
        lsp_range = {"start": {"line": r["start"]["line"] - 1, "character": r["start"]["column"] - 1},
                     "end": {"line": r["end"]["line"] - 1, "character": r["end"]["column"] - 1}} if r else \
            {"start": {"line": 0, "character": 0}, "end": {"line": 0, "character": 0}}
        expected.setdefault(uri(os.path.abspath(d["file"])) if d["file"].startswith("/") else d["file"], []).append(
            (d["code"], severities[d["severity"]], json.dumps(lsp_range, sort_keys=True), d["message"]))
    return expected


def published(diagnostics):
    return [(d.get("code"), d["severity"], json.dumps(d["range"], sort_keys=True), d["message"]) for d in diagnostics]


work = tempfile.mkdtemp()
bad = os.path.join(work, "bad.vox")
rules = os.path.join(work, "bad.rules")
with open(rules, "w") as f:
    f.write("I;FFZ;tunnel;1\nC;FXZ;tunnel;1\n")
bad_text = ("const UNUSED = 3;\nworld {\n  size = [16, 16, 16];\n}\nlsystem net {\n  rules = \"bad.rules\";\n}\n"
            "grammar g { rule r { size = [1,1,1]; symbol { [PRES 3] } } }\npipeline { start; missing; }\n")
with open(bad, "w") as f:
    f.write(bad_text)

client = Client(voxc)
check("request_before_initialize", client.request("textDocument/hover", {}).get("error", {}).get("code") == -32002)
init = client.request("initialize", {"processId": None, "rootUri": None, "capabilities": {}})
caps = init.get("result", {}).get("capabilities", {})
check("initialize", caps.get("hoverProvider") is True and "completionProvider" in caps
      and caps.get("definitionProvider") is True
      and caps.get("textDocumentSync", {}).get("change") == 1, init)
client.notify("initialized", {})

# didOpen: the same diagnostics as `voxc check`, the rule file's on the rule file
client.notify("textDocument/didOpen", {"textDocument": {"uri": uri(bad), "languageId": "vox", "version": 1,
                                                        "text": bad_text}})
expected = check_json(bad)
got_bad = published(client.diagnostics_for(uri(bad)))
got_rules = published(client.diagnostics_for(uri(rules)))
check("did_open_diagnostics_equal_check", got_bad == expected.get(uri(bad)), (got_bad, expected))
check("rule_file_diagnostics_on_its_uri", got_rules and got_rules == expected.get(uri(rules)), (got_rules, expected))
check("diagnostics_have_several_codes", len({d[0] for d in got_bad}) >= 2, got_bad)

for example in ["overhang", "scene", "fields", "caves"]:
    path = os.path.join(src, "examples", example + ".vox")
    text = open(path).read()
    client.notify("textDocument/didOpen", {"textDocument": {"uri": uri(path), "languageId": "vox", "version": 1,
                                                            "text": text}})
    got = published(client.diagnostics_for(uri(path)))
    check("example_%s_equals_check" % example, got == check_json(path).get(uri(path), []), got)

# Columns: the checker counts characters, LSP counts UTF-16 units; a character beyond the basic
# plane before the error on its line is two units.
wide = os.path.join(work, "wide.vox")
wide_text = "world { size = [8, 8, 8]; }\n/* \U0001F600 */ pipeline { start; nope; }\n"
with open(wide, "w") as f:
    f.write(wide_text)
client.notify("textDocument/didOpen", {"textDocument": {"uri": uri(wide), "languageId": "vox", "version": 1,
                                                        "text": wide_text}})
wide_got = client.diagnostics_for(uri(wide))
wide_check = check_json(wide)[uri(wide)]
check_start = json.loads(wide_check[0][2])["start"]
check("utf16_columns", len(wide_got) == 1 and wide_got[0]["range"]["start"] ==
      {"line": check_start["line"], "character": check_start["character"] + 1}
      and wide_text.split("\n")[1].encode("utf-16-le")[2 * wide_got[0]["range"]["start"]["character"]:].decode(
          "utf-16-le").startswith("nope"), (wide_got, wide_check))

# didChange: a typo appears, then goes again
overhang = os.path.join(src, "examples", "overhang.vox")
overhang_text = open(overhang).read()
typo = overhang_text.replace("pipeline { start; overhang; }", "pipeline { start; overhnag; }")
client.notify("textDocument/didChange", {"textDocument": {"uri": uri(overhang), "version": 2},
                                         "contentChanges": [{"text": typo}]})
changed = client.diagnostics_for(uri(overhang))
check("did_change_reports_typo", [d.get("code") for d in changed] == ["E0002"] and "overhang" in changed[0]["message"],
      changed)
client.notify("textDocument/didChange", {"textDocument": {"uri": uri(overhang), "version": 3},
                                         "contentChanges": [{"text": overhang_text}]})
check("did_change_clears", client.diagnostics_for(uri(overhang)) == [])


def slow_text(tag):
    """A valid document whose check takes a while (500 noise fields, each lowered and range-checked, one
    kernel each: the pipeline's limit is 512)."""
    fields = "".join("field f%d = fbm(wp * %d.5, 5, 2.0, 0.5, %d) + perlin3(wp * 0.%d, 1) * %d.0 - wy;\n"
                     % (i, i % 7 + 1, i, i + 1, i % 5 + 1) for i in range(FIELDS))
    return "// %s\nworld { size = [32, 32, 32]; }\n%spipeline { start; %s }\n" % (
        tag, fields, " ".join("union f%d;" % i for i in range(FIELDS)))


FIELDS = 500
slow = os.path.join(work, "slow.vox")
slow_base = slow_text("base")

# A hover never waits for a check: while the slow document's check runs on the checker's thread,
# a hover in another document answers at once, before that check's diagnostics.
client.notify("textDocument/didOpen", {"textDocument": {"uri": uri(slow), "languageId": "vox", "version": 1,
                                                        "text": slow_base}})
overhang_path = os.path.join(src, "examples", "overhang.vox")
started = time.monotonic()
hover_during = client.request("textDocument/hover", {"textDocument": {"uri": uri(overhang_path)},
                                                     "position": {"line": 0, "character": 0}})
hover_ms = (time.monotonic() - started) * 1000
slow_published_before = [n for n in client.notifications if n["params"]["uri"] == uri(slow)]
slow_first = client.diagnostics_for(uri(slow))
check_ms = (time.monotonic() - started) * 1000
check("hover_during_check_answers_within_500ms", "result" in hover_during and hover_ms < 500, hover_ms)
check("hover_answered_before_the_check_finished", not slow_published_before and check_ms > hover_ms,
      (hover_ms, check_ms, len(slow_published_before)))
check("slow_document_is_valid", slow_first == [], slow_first[:3])

# Edits typed while a slow check runs are not checked one by one: only the newest waiting text
# is, and what is published last is its diagnostics.
for version in range(2, 8):
    text = slow_base + "// edit %d\n" % version + ("pipeline { nope; }\n" if version == 7 else "")
    client.notify("textDocument/didChange", {"textDocument": {"uri": uri(slow), "version": version},
                                             "contentChanges": [{"text": text}]})
slow_published = []
while not slow_published or [d.get("code") for d in slow_published[-1]] != ["E0003"]:
    slow_published.append(client.diagnostics_for(uri(slow)))
    if len(slow_published) > 6:
        break
check("waiting_edits_coalesced", 1 <= len(slow_published) <= 3, len(slow_published))
check("newest_edit_published", [d.get("code") for d in slow_published[-1]] == ["E0003"]
      and slow_published[-1][0]["range"]["start"]["line"] == slow_base.count("\n") + 1, slow_published[-1:])

# valley.vox's check no longer generates its terrain: after an edit, completion answers at once
# and the diagnostics follow.
valley = os.path.join(src, "examples", "valley.vox")
valley_text = open(valley).read()
client.notify("textDocument/didOpen", {"textDocument": {"uri": uri(valley), "languageId": "vox", "version": 1,
                                                        "text": valley_text}})
check("valley_opens_clean", client.diagnostics_for(uri(valley)) == [])
edited = valley_text + "// edit\n"
client.notify("textDocument/didChange", {"textDocument": {"uri": uri(valley), "version": 2},
                                         "contentChanges": [{"text": edited}]})
started = time.monotonic()
response = client.request("textDocument/completion", {"textDocument": {"uri": uri(valley)},
                                                      "position": {"line": edited.count("\n"), "character": 0}})
completion_ms = (time.monotonic() - started) * 1000
check("valley_completion_after_edit_within_500ms", response.get("result", {}).get("items") and completion_ms < 500,
      completion_ms)
check("valley_edit_published", client.diagnostics_for(uri(valley)) == [])
print("measured: hover during a check %.1f ms (the check took %.0f ms), valley completion after an edit %.1f ms"
      % (hover_ms, check_ms, completion_ms))


def position_of(text, needle, offset=0):
    index = text.index(needle) + offset
    line = text.count("\n", 0, index)
    return {"line": line, "character": index - (text.rfind("\n", 0, index) + 1)}


def hover(path, text, needle, offset=0):
    response = client.request("textDocument/hover", {"textDocument": {"uri": uri(path)},
                                                     "position": position_of(text, needle, offset)})
    result = response.get("result")
    return result["contents"]["value"] if result else None


fields = os.path.join(src, "examples", "fields.vox")
fields_text = open(fields).read()
h = hover(fields, fields_text, "fbm(", 1)
check("hover_builtin_function", h and "fbm(" in h and "->" in h, h)
h = hover(overhang, overhang_text, "GEQ", 1)
check("hover_symbol_operator", h and "d >= v" in h, h)
h = hover(overhang, overhang_text, "box {", 1)
check("hover_start_shape_lists_keys", h and "start shape" in h and "`min = ...;`" in h and "required" in h, h)
h = hover(overhang, overhang_text, "max = [24", 1)
check("hover_shape_key", h and "key of the `box` shape" in h and "in [" in h, h)
h = hover(fields, fields_text, "solid(segment", 1)
check("hover_user_function", h and "fn solid(distance: float, r: float) -> float" in h, h)
h = hover(overhang, overhang_text, "iterations", 1)
check("hover_block_key", h and "a key of the `grammar` block" in h, h)

definition = client.request("textDocument/definition", {"textDocument": {"uri": uri(fields)},
                                                        "position": position_of(fields_text, "solid(segment", 1)})
declared = position_of(fields_text, "fn solid")
target = definition.get("result") or {}
check("definition_of_user_function", target.get("uri") == uri(fields)
      and target.get("range", {}).get("start", {}).get("line") == declared["line"], (definition, declared))


def completion(path, text, needle, offset):
    response = client.request("textDocument/completion", {"textDocument": {"uri": uri(path)},
                                                          "position": position_of(text, needle, offset)})
    return response["result"]["items"]


items = completion(fields, fields_text, "perlin3(wp", 3)
labels = [i["label"] for i in items]
check("completion_builtins_by_prefix", "perlin3" in labels and all(l.lower().startswith("per") for l in labels), labels)
perlin = next((i for i in items if i["label"] == "perlin3"), {})
check("completion_carries_registry_doc", "perlin3(" in perlin.get("detail", "") and perlin.get("documentation"), perlin)
items = completion(fields, fields_text, "  let height", 2)
labels = [i["label"] for i in items]
check("completion_names_and_builtins", {"ROCK", "SEED", "solid", "segment", "ground", "crumble", "fbm", "GEQ", "box"}
      <= set(labels), labels)
items = completion(overhang, overhang_text, "box { min", 6)
labels = [i["label"] for i in items]
check("completion_shape_keys_first", labels[:3] == ["min", "max", "value"] or {"min", "max", "value"} <= set(labels[:5]),
      labels[:8])

# malformed input: answered with errors, the server keeps serving
client.send_raw(b"Content-Length: 9\r\n\r\n{not json")
check("bad_json_parse_error", client.response(None)["error"]["code"] == -32700)
client.send_raw(b"Content-Length: 4000\r\n\r\n" + b"[" * 4000)
check("deep_nesting_refused", client.response(None)["error"]["code"] == -32700)
client.send_raw(b"X-Nothing: 1\r\n\r\n")
check("missing_content_length", client.response(None)["error"]["code"] == -32700)
oversized = 40 << 20  # over the 32 MiB cap: read past in bounded memory, then refused
client.send_raw(b"Content-Length: %d\r\n\r\n" % oversized + b" " * oversized)
check("oversized_message_refused", client.response(None)["error"]["code"] == -32700)
check("still_serving", "GEQ" in (hover(overhang, overhang_text, "GEQ", 1) or ""))
client.process.kill()
client.process.wait()

client = Client(voxc)
client.request("initialize", {"capabilities": {}})
check("unknown_method", client.request("voxc/frobnicate")["error"]["code"] == -32601)
check("bad_params", client.request("textDocument/hover", {"position": 3})["error"]["code"] == -32602)
shutdown = client.request("shutdown")
check("shutdown", "result" in shutdown and shutdown["result"] is None and "error" not in shutdown, shutdown)
check("request_after_shutdown", client.request("textDocument/hover", {})["error"]["code"] == -32600)
client.notify("exit", {})
check("exit_after_shutdown_is_0", client.process.wait(timeout=30) == 0)

client = Client(voxc)
client.request("initialize", {"capabilities": {}})
client.process.stdin.close()
check("end_without_exit_is_1", client.process.wait(timeout=30) == 1)

def diagnose_then_shut_down(name, path, text, check_diagnostics):
    """Opens `text` as `path` in a new server, hands its diagnostics to check_diagnostics(client, got),
    then checks that shutdown and exit still work. A watchdog kills a server that stopped
    answering, so a hang fails here instead of stalling the test."""
    client = Client(voxc)
    watchdog = threading.Timer(60, client.process.kill)
    watchdog.start()
    try:
        client.request("initialize", {"capabilities": {}})
        client.notify("textDocument/didOpen", {"textDocument": {"uri": uri(path), "languageId": "vox", "version": 1,
                                                                "text": text}})
        check_diagnostics(client, client.diagnostics_for(uri(path)))
        shutdown = client.request("shutdown")
        check(name + "_shutdown", "result" in shutdown and "error" not in shutdown, shutdown)
        client.notify("exit", {})
        check(name + "_exit_0", client.process.wait(timeout=30) == 0)
    except (EOFError, OSError, subprocess.TimeoutExpired) as e:
        check(name + "_answered", False, "the server stopped answering: %r" % e)
    finally:
        watchdog.cancel()
        client.process.kill()


# A document naming the server's own input (/dev/stdin, a pipe under an editor) or a FIFO as its
# rule file still gets its diagnostics and the server keeps serving: the check refuses what is
# not a regular file without reading it.
os.mkfifo(os.path.join(work, "rules.fifo"))
streams = os.path.join(work, "streams.vox")


def check_streams(client, got):
    check("stream_rule_files_diagnosed",
          [(d.get("code"), d["range"]["start"]["line"]) for d in got] == [("E0100", 2), ("E0100", 5)]
          and "/dev/stdin': it is a FIFO" in got[0]["message"] and "rules.fifo': it is a FIFO" in got[1]["message"], got)
    check("stream_rule_files_still_serving", "result" in client.request("textDocument/hover", {
        "textDocument": {"uri": uri(streams)}, "position": {"line": 2, "character": 3}}))


diagnose_then_shut_down("stream_rule_files", streams,
                        "world { size = [16, 16, 16]; }\nlsystem from_stdin {\n  rules = \"/dev/stdin\";\n}\n"
                        "lsystem from_fifo {\n  rules = \"rules.fifo\";\n}\n", check_streams)

# Heightmap and mesh files: one that is missing and one that is a FIFO are diagnostics at their
# `file =` values.
os.mkfifo(os.path.join(work, "rock.fifo"))
diagnose_then_shut_down(
    "input_files", os.path.join(work, "inputs.vox"),
    "world { size = [16, 16, 16]; }\nheightmap hills {\n  file = \"missing.png\";\n  size = [16, 16];\n"
    "  height = [0, 8];\n}\nmesh rock {\n  file = \"rock.fifo\";\n}\n"
    "field g = clamp(hills(wx, wz) - wy, 0, 1) - clamp(-rock(wp), 0, 1);\npipeline { start; set g; }\n",
    lambda client, got: check(
        "input_files_diagnosed_at_their_key",
        [(d.get("code"), d["range"]["start"]["line"], d["range"]["start"]["character"]) for d in got]
        == [("E0100", 2, 9), ("E0100", 7, 9)]
        and "missing.png" in got[0]["message"] and "rock.fifo': it is a FIFO" in got[1]["message"], got))

finish()
