#!/usr/bin/env python3
"""A deterministic mutation test of the one front door through the CLI (issue 31).

Every command line of tests/data/bad_requests.json is mutated the same way each run (each token
dropped, doubled, and each value replaced by each of a list of hostile values: empty, zero,
negative, nan, inf, huge and tiny numbers, 300 bytes, an escape sequence, a FIFO, a folder,
/dev/zero, ...), written as a corpus of fuzz_cli_args inputs (one argument per line; the @
tokens stand for the scratch folder's special files) and replayed through that target in its
check-only mode, whose property is the fuzzers': exit 0 or 2, never a crash, a hang or another
code (it aborts otherwise); and every message is one inert line (no raw escape byte, no value
echoed whole). The same corpus can seed libFuzzer (docs/reliability.md).

usage: mutate_bad_requests.py TABLE FUZZ_CLI_ARGS [OUT_DIR]
"""
import json
import pathlib
import subprocess
import sys
import tempfile

HOSTILE = ["", "0", "-1", "nan", "inf", "-inf", "1e308", "1e-308", "4294967298", "x" * 300, "\x1b]0;t\x07\x1b[2J",
           ",", ",,", "a=b=c", "=", "--", "-", "@fifo", "@dir", "@zero", "@null", "@empty", "@scene"]


def tokens(row):
    """The row's command line with its inputs as the fuzz target's tokens."""
    out = []
    for arg in row["cli"]:
        if arg.startswith("{dir}/"):
            name = arg[len("{dir}/"):]
            arg = {"exp.json": "@scene", "fifo": "@fifo"}.get(name, name)  # an output: a name in the cwd
        out.append(arg)
    return out


def mutations(args):
    yield args
    for i in range(1, len(args)):
        yield args[:i] + args[i + 1:]                 # dropped
        yield args[:i + 1] + args[i:]                 # given twice
        if not args[i].startswith("--"):
            for value in HOSTILE:
                yield args[:i] + [value] + args[i + 1:]  # a hostile value


def main():
    table = json.loads(pathlib.Path(sys.argv[1]).read_text())
    target = sys.argv[2]
    with tempfile.TemporaryDirectory() as scratch:
        out = pathlib.Path(sys.argv[3]) if len(sys.argv) > 3 else pathlib.Path(scratch) / "corpus"
        out.mkdir(parents=True, exist_ok=True)
        count = 0
        for row in table:
            if "cli" not in row:
                continue
            for args in mutations(tokens(row)):
                (out / f"m{count:05d}").write_text("\n".join(args), encoding="utf-8")
                count += 1
        # In a scratch folder: an output named by a mutation is a relative name there.
        r = subprocess.run([target, str(out)], cwd=scratch, capture_output=True, text=True, errors="replace")
        print(r.stdout.strip())
        if r.returncode != 0:
            print(r.stderr[-4000:], file=sys.stderr)
            return 1
        # Every refusal one inert line: no raw escape or bell byte, no value echoed whole.
        for line in r.stderr.splitlines():
            if "\x1b" in line or "\x07" in line or len(line) > 1500:
                print("a message echoes a raw or whole value:", repr(line[:300]), file=sys.stderr)
                return 1
        print(f"{count} mutated command lines from {sum('cli' in r for r in table)} bad requests: exit 0 or 2 each")
    return 0


if __name__ == "__main__":
    sys.exit(main())
