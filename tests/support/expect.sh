# Sourced by the shell tests that run voxc as a user would (tests/cli, tests/render, tests/pipeline,
# tests/edit, tests/mesh, tests/world, tests/viewer): checks that count into `passed` and `failed`,
# and the summary line.
passed=0
failed=0

# expect NAME WANT_EXIT PATTERN -- COMMAND...: the exit code must be WANT_EXIT and the combined
# output must match the extended regex PATTERN (empty: not checked). A failure shows the output's
# last 20 lines (where an error ends up).
expect() {
    local name=$1 want=$2 pattern=$3
    shift 4
    local out code
    out=$("$@" 2>&1)
    code=$?
    if [ "$code" -ne "$want" ]; then
        echo "FAIL $name: exit $code, want $want"; echo "$out" | tail -20; failed=$((failed + 1)); return
    fi
    if [ -n "$pattern" ] && ! grep -Eq -- "$pattern" <<<"$out"; then
        echo "FAIL $name: output does not match /$pattern/"; echo "$out" | tail -20; failed=$((failed + 1)); return
    fi
    echo "ok   $name"; passed=$((passed + 1))
}

# expect_no_file NAME PATH: a failed command must not leave an output (or temp) file behind.
expect_no_file() {
    if compgen -G "$2*" >/dev/null; then
        echo "FAIL $1: $2 exists after a failure"; failed=$((failed + 1))
    else
        echo "ok   $1"; passed=$((passed + 1))
    fi
}

# expect_same NAME A B: the files must be byte-identical (a refused or failed command kept the user's file).
expect_same() {
    if cmp -s "$2" "$3"; then
        echo "ok   $1"; passed=$((passed + 1))
    else
        echo "FAIL $1: $2 differs from $3"; failed=$((failed + 1))
    fi
}

# pass NAME / fail NAME: record a check the script made itself.
pass() { echo "ok   $*"; passed=$((passed + 1)); }
fail() { echo "FAIL $*"; failed=$((failed + 1)); }

# finish: prints "N passed, N failed" and exits non-zero after any failure.
finish() {
    echo "$passed passed, $failed failed"
    [ "$failed" -eq 0 ]
    exit
}
