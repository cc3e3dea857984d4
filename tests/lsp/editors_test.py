#!/usr/bin/env python3
"""The editor support in editors/ (docs/editors.md).

Usage: editors_test.py VOXC SOURCE_DIR. The TextMate grammar's patterns compile, its cell
operators are exactly the registries' operators (as `voxc lsp` completes them), it scopes an
example's comments, calls, operators and keys; the VS Code extension packs with `npm pack`.
Prints "N passed, N failed" last.
"""
import json
import os
import re
import shutil
import subprocess
import sys
import tempfile

from lsp_client import Client, check, finish, uri

voxc, src = sys.argv[1], sys.argv[2]


extension = os.path.join(src, "editors", "vscode")
grammar = json.load(open(os.path.join(extension, "syntaxes", "vox.tmLanguage.json")))
repository = grammar["repository"]


def patterns(node):
    if "match" in node:
        yield node["match"]
    for key in ("begin", "end"):
        if key in node:
            yield node[key]
    for child in node.get("patterns", []):
        yield from patterns(child)


compiled = []
for name, node in repository.items():
    for pattern in patterns(node):
        try:
            compiled.append(re.compile(pattern))
        except re.error as error:
            check("pattern_%s_compiles" % name, False, error)
check("grammar_patterns_compile", len(compiled) >= 10)

# The operators the server completes come from the registries; the grammar must name each.
client = Client(voxc)
client.request("initialize", {"capabilities": {}})
path = os.path.join(tempfile.mkdtemp(), "empty.vox")
client.notify("textDocument/didOpen", {"textDocument": {"uri": uri(path), "languageId": "vox", "version": 1, "text": ""}})
items = client.request("textDocument/completion", {"textDocument": {"uri": uri(path)},
                                                   "position": {"line": 0, "character": 0}})["result"]["items"]
client.request("shutdown")
client.notify("exit", {})
client.process.wait(timeout=30)
registry_operators = {i["label"] for i in items if i["kind"] == 24}
grammar_operators = set(re.search(r"\(([A-Z|]+)\)", repository["operators"]["match"]).group(1).split("|"))
check("grammar_operators_are_the_registries", registry_operators and grammar_operators == registry_operators,
      (sorted(grammar_operators), sorted(registry_operators)))
functions = [i["label"] for i in items if i["kind"] == 3]
call = re.compile(repository["calls"]["match"])
check("grammar_scopes_every_builtin_call", functions and all(call.search(f + "(x)") for f in functions))

fields = open(os.path.join(src, "examples", "fields.vox")).read()
check("grammar_comment", re.search(repository["comments"]["patterns"][0]["match"], fields, re.M))
check("grammar_key", re.compile(repository["keys"]["match"]).search("  size = [64, 64, 64];").group(1) == "size")
check("grammar_block", re.compile(repository["blocks"]["match"]).search("grammar crumble {").group(2) == "crumble")
check("grammar_not_a_key_in_comparison", not re.compile(repository["keys"]["match"]).search("y == 3"))

# The extension packs (the tarball `npm pack` makes) with everything package.json points at.
manifest = json.load(open(os.path.join(extension, "package.json")))
work = tempfile.mkdtemp()
shutil.copytree(extension, os.path.join(work, "vscode"))
pack = subprocess.run(["npm", "pack", "--json", "--pack-destination", work], cwd=os.path.join(work, "vscode"),
                      capture_output=True, text=True)
check("npm_pack", pack.returncode == 0, pack.stderr)
if pack.returncode == 0:
    packed = json.loads(pack.stdout)[0]
    files = {f["path"] for f in packed["files"]}
    wanted = {"package.json", "extension.js", "language-configuration.json", "syntaxes/vox.tmLanguage.json"}
    check("npm_pack_files", wanted <= files, files)
    check("npm_pack_tarball", os.path.getsize(os.path.join(work, packed["filename"])) > 0)
check("package_points_at_grammar", manifest["contributes"]["grammars"][0]["path"] == "./syntaxes/vox.tmLanguage.json"
      and manifest["contributes"]["languages"][0]["extensions"] == [".vox"])

finish()
