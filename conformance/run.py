#!/usr/bin/env python3
"""Runs any qmc decoder over the conformance vectors (spec/qmc-format.md 10.3).

    conformance/run.py --decoder "mydec {in} {out}" [--manifest conformance/MANIFEST]
                       [--only PATTERN] [--skip-ordr] [--skip-attr] [--skip-flbl] [--strict-errors] [--jobs N] [--timeout S]

The decoder command is a shell command line in which {in} is replaced by the
vector's path and {out} by the path of a file to write, both quoted for the
shell. For a valid vector the command must exit 0 and write the canonical
output (spec 10.2, 12.9, 13.10) to {out}; its SHA-256 must be the manifest's.
For an invalid vector it must exit with a non-zero status; with
--strict-errors it must also print the manifest's error identifier (spec 9)
as a word somewhere on stdout or stderr. A command killed by a signal (or
exiting with a status above 128, as a shell reports one) or still running
after the timeout fails either way.

Prints one line per vector (PASS, FAIL with the reason, or SKIP), then the
summary "N passed, N failed" (", N skipped" added when vectors were skipped).
Exit status: 0 if nothing failed, 1 if a vector failed, 2 for bad usage (an
unreadable manifest, a command without {in} and {out}, no vector selected).
Python 3 standard library only.
"""

import argparse
import concurrent.futures
import fnmatch
import hashlib
import os
import re
import shlex
import signal
import subprocess
import sys
import tempfile

EXIT_OK, EXIT_FAILED, EXIT_USAGE = 0, 1, 2

# Spec 10.1: vectors of the ancillary chunk oRDR (4.5), which a decoder
# without 4.5 is not checked on.
ORDR_PREFIXES = ("valid_ordr_", "invalid_ordr_")
ATTR_PREFIXES = ("valid_attr_", "invalid_attr_")
FLBL_PREFIXES = ("valid_flbl_", "invalid_flbl_")


class UsageError(Exception):
    pass


class Vector:
    def __init__(self, kind, path, expected):
        self.kind = kind          # "valid" or "invalid"
        self.path = path          # absolute
        self.expected = expected  # SHA-256 hex digest or error identifier
        self.name = os.path.splitext(os.path.basename(path))[0]


def read_manifest(manifest):
    """Spec 10.1: 'valid PATH SHA256' or 'invalid PATH ERROR', PATH relative to the manifest."""
    base = os.path.dirname(os.path.abspath(manifest))
    vectors = []
    try:
        with open(manifest, encoding="utf-8") as f:
            lines = f.read().splitlines()
    except OSError as e:
        raise UsageError(f"cannot read the manifest: {e}")
    for number, line in enumerate(lines, 1):
        if not line.strip() or line.startswith("#"):
            continue
        fields = line.split()
        if len(fields) != 3 or fields[0] not in ("valid", "invalid"):
            raise UsageError(f"{manifest}:{number}: expected 'valid PATH SHA256' or 'invalid PATH ERROR'")
        vectors.append(Vector(fields[0], os.path.join(base, fields[1]), fields[2]))
    return vectors


def command_for(template, in_path, out_path):
    return template.replace("{in}", shlex.quote(in_path)).replace("{out}", shlex.quote(out_path))


def run_decoder(template, vector, work_dir, timeout):
    """Returns (exit status or None on timeout, output bytes or None, stdout + stderr text)."""
    out_path = os.path.join(work_dir, vector.name + ".out")
    # Its own process group, so that a timeout ends the decoder and not only
    # the shell that started it.
    proc = subprocess.Popen(command_for(template, vector.path, out_path), shell=True, stdin=subprocess.DEVNULL,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, start_new_session=True)
    try:
        stdout, stderr = proc.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        proc.communicate()
        return None, None, ""
    text = (stdout + b"\n" + stderr).decode("utf-8", errors="replace")
    output = None
    if os.path.exists(out_path):
        with open(out_path, "rb") as f:
            output = f.read()
        os.remove(out_path)
    return proc.returncode, output, text


def mentions_identifier(text, identifier):
    return re.search(r"(?<![A-Za-z0-9_])" + re.escape(identifier) + r"(?![A-Za-z0-9_])", text) is not None


def check(vector, template, work_dir, timeout, strict_errors):
    """The reason the vector fails, or None if it passes."""
    if not os.path.isfile(vector.path):
        return f"vector file missing: {vector.path}"
    status, output, text = run_decoder(template, vector, work_dir, timeout)
    if status is None:
        return f"no answer within {timeout:g} s"
    if status < 0 or status > 128:  # a shell reports a signal as 128 + its number
        return f"decoder killed by a signal (exit status {status})"
    if vector.kind == "valid":
        if status != 0:
            return f"rejected (exit status {status}), should decode"
        if output is None:
            return "exit status 0 but nothing written to {out}"
        digest = hashlib.sha256(output).hexdigest()
        if digest != vector.expected:
            return f"canonical output digest {digest}, expected {vector.expected}"
        return None
    if status == 0:
        return f"accepted (exit status 0), should be rejected as {vector.expected}"
    if strict_errors and not mentions_identifier(text, vector.expected):
        return f"rejected (exit status {status}) without naming {vector.expected}"
    return None


def select(vectors, only, skip_ordr, skip_attr=False, skip_flbl=False):
    """(vector, skip reason or None) for the vectors --only keeps."""
    chosen = []
    for v in vectors:
        if only and not fnmatch.fnmatchcase(v.name, only):
            continue
        skipped = [f"{chunk} vector (--skip-{flag}, spec 10.1)"
                   for skip, prefixes, chunk, flag in ((skip_ordr, ORDR_PREFIXES, "oRDR", "ordr"),
                                                      (skip_attr, ATTR_PREFIXES, "aTTR", "attr"),
                                                      (skip_flbl, FLBL_PREFIXES, "fLBL", "flbl"))
                   if skip and v.name.startswith(prefixes)]
        chosen.append((v, skipped[0] if skipped else None))
    return chosen


def parse_args(argv):
    here = os.path.dirname(os.path.abspath(__file__))
    p = argparse.ArgumentParser(description="Run a qmc decoder over the conformance vectors (spec 10.3).")
    p.add_argument("--decoder", required=True,
                   help='shell command with {in} and {out}, e.g. "mydec {in} {out}"')
    p.add_argument("--manifest", default=os.path.join(here, "MANIFEST"), help="default: MANIFEST beside this script")
    p.add_argument("--only", metavar="PATTERN", help="only vectors whose name (no .qmc) matches this glob")
    p.add_argument("--skip-ordr", action="store_true", help="skip the valid_ordr_*/invalid_ordr_* vectors (spec 10.1)")
    p.add_argument("--skip-attr", action="store_true",
                   help="skip the valid_attr_*/invalid_attr_* vectors, for a decoder without section 15 (spec 10.1)")
    p.add_argument("--skip-flbl", action="store_true",
                   help="skip the valid_flbl_*/invalid_flbl_* vectors, for a decoder without section 16 (spec 10.1)")
    p.add_argument("--strict-errors", action="store_true",
                   help="a rejection must also print the manifest's error identifier (spec 9)")
    p.add_argument("--jobs", type=int, default=1, metavar="N", help="vectors decoded at once (default 1)")
    p.add_argument("--timeout", type=float, default=60.0, metavar="S", help="seconds per vector (default 60)")
    args = p.parse_args(argv)
    if "{in}" not in args.decoder or "{out}" not in args.decoder:
        p.error("--decoder needs both {in} and {out}")
    if args.jobs < 1 or args.timeout <= 0:
        p.error("--jobs must be at least 1 and --timeout above 0")
    return args


def main(argv):
    args = parse_args(argv)
    try:
        chosen = select(read_manifest(args.manifest), args.only, args.skip_ordr, args.skip_attr, args.skip_flbl)
    except UsageError as e:
        print(f"run.py: {e}", file=sys.stderr)
        return EXIT_USAGE
    if not chosen:
        print("run.py: no vector selected", file=sys.stderr)
        return EXIT_USAGE
    passed = failed = skipped = 0
    with tempfile.TemporaryDirectory(prefix="qmc-conformance-") as work_dir, \
            concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        def verdict(item):
            vector, skip = item
            return skip, None if skip else check(vector, args.decoder, work_dir, args.timeout, args.strict_errors)
        for (vector, _), (skip, problem) in zip(chosen, pool.map(verdict, chosen)):
            label = f"{vector.kind} {vector.name}"
            if skip:
                skipped += 1
                print(f"SKIP {label}: {skip}")
            elif problem:
                failed += 1
                print(f"FAIL {label}: {problem}")
            else:
                passed += 1
                print(f"PASS {label}")
            sys.stdout.flush()
    summary = f"{passed} passed, {failed} failed"
    if skipped:
        summary += f", {skipped} skipped"
    print(summary)
    return EXIT_FAILED if failed else EXIT_OK


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
