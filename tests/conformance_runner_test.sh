#!/usr/bin/env bash
# conformance/run.py (spec 10.3) must fail decoders that do not conform:
# one that accepts everything writing nothing, one that rejects everything,
# one that writes the wrong bytes, one that hangs, one that crashes; and it
# must skip exactly the oRDR vectors with --skip-ordr.
# Usage: conformance_runner_test.sh PYTHON3 CONFORMANCE_DIR QMC
set -u
python=$1 dir=$2 qmc=$3
runner=("$python" "$dir/run.py" --manifest "$dir/MANIFEST")
reference="$qmc decode --canonical --quiet {in} {out}"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
passed=0 failed=0
check() {  # check NAME EXPECTED_EXIT RUNNER-ARGS...
  local name=$1 want=$2; shift 2
  "${runner[@]}" "$@" >"$work/out" 2>"$work/err"
  local got=$?
  if [ "$got" -eq "$want" ]; then passed=$((passed + 1)); else
    failed=$((failed + 1)); echo "FAIL $name: exit $got, expected $want"; cat "$work/out" "$work/err"; fi
}
last_line() {  # last_line NAME EXPECTED: the summary line, exactly
  local got; got=$(tail -n 1 "$work/out")
  if [ "$got" = "$2" ]; then passed=$((passed + 1)); else
    failed=$((failed + 1)); echo "FAIL $1: summary '$got', expected '$2'"; fi
}
contains() {  # contains NAME PATTERN
  if grep -q -- "$2" "$work/out"; then passed=$((passed + 1)); else
    failed=$((failed + 1)); echo "FAIL $1: '$2' not in output:"; cat "$work/out"; fi
}

valid=$(grep -c '^valid ' "$dir/MANIFEST")
invalid=$(grep -c '^invalid ' "$dir/MANIFEST")
total=$((valid + invalid))

# Exits 0 and writes nothing: every vector fails.
check accept-all 1 --decoder "true {in} {out}" --jobs 2
last_line accept-all-summary "0 passed, $total failed"
contains accept-all-valid-reason "FAIL valid valid_tetrahedron: exit status 0 but nothing written"
contains accept-all-invalid-reason "FAIL invalid invalid_crc: accepted (exit status 0), should be rejected as bad_crc"

# Rejects everything: the invalid vectors pass unless --strict-errors asks
# for the identifier, which `false` never prints.
check reject-all 1 --decoder "false {in} {out}" --jobs 2
last_line reject-all-summary "$invalid passed, $valid failed"
check reject-all-strict 1 --decoder "false {in} {out}" --only 'invalid_polygon_*' --strict-errors
contains reject-all-strict-reason "without naming bad_symbol"

# Wrong bytes: the input copied to the output.
check wrong-output 1 --decoder "cp {in} {out}" --only valid_tetrahedron
contains wrong-output-reason "canonical output digest"

# A hang and a crash are failures, not rejections.
check timeout 1 --decoder "sleep 30 # {in} {out}" --only invalid_crc --timeout 0.5
contains timeout-reason "no answer within 0.5 s"
check crash 1 --decoder "sh -c 'kill -SEGV \$\$' # {in} {out}" --only invalid_crc
contains crash-reason "killed by a signal"

# --skip-ordr skips valid_ordr_* and invalid_ordr_* only: invalid_loop_with_ordr
# binds every decoder (spec 12.1), invalid_attr_after_ordr and
# invalid_flbl_after_ordr every decoder of sections 15 and 16.
ordr=$(grep -c -E '^(valid|invalid) +vectors/(valid|invalid)_ordr_' "$dir/MANIFEST")
check skip-ordr 0 --decoder "$reference" --only '*ordr*' --skip-ordr --strict-errors
last_line skip-ordr-summary "3 passed, 0 failed, $ordr skipped"
contains skip-ordr-loop "PASS invalid invalid_loop_with_ordr"
# --skip-attr skips the aTTR vectors (spec 10.1), not the geometry images' attribute planes.
attr=$(grep -c -E '^(valid|invalid) +vectors/(valid|invalid)_attr_' "$dir/MANIFEST")
check skip-attr 0 --decoder "$reference" --only '*attr*' --skip-attr --strict-errors
last_line skip-attr-summary "2 passed, 0 failed, $attr skipped"
flbl=$(grep -c -E '^(valid|invalid) +vectors/(valid|invalid)_flbl_' "$dir/MANIFEST")
check skip-flbl 0 --decoder "$reference" --only '*flbl*' --skip-flbl --strict-errors
last_line skip-flbl-summary "0 passed, 0 failed, $flbl skipped"

check no-out-placeholder 2 --decoder "true {in}"
check nothing-selected 2 --decoder "$reference" --only 'no_such_vector'
echo "conformance runner: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
