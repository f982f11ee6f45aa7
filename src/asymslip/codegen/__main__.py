"""``python -m asymslip.codegen {generate,verify,check,report}``: the Makefile's entry points.

``generate`` runs every derivation once and writes, from that one run's records, the NumPy
package (``asymslip_gen/``, with ``formulas.json``), the C, Fortran and MATLAB/Octave trees
(``c/``, ``fortran/``, ``matlab/``) and the derivation report (``report/derivation.md``) under
the generated root.  ``check`` does the same under two hash seeds into a temporary folder and
diffs every tree against the committed one.
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

from .runner import (
    ERROR_MAP_FILE,
    REPORT_FOLDER,
    check_fresh,
    print_verification,
    render_all,
    run_derivations,
    write_generated,
)

ROOT = Path.cwd()


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        prog="python -m asymslip.codegen",
        description="Run the SymPy derivations and write, verify or freshness-check the "
        "generated code (NumPy, C, Fortran, MATLAB/Octave) and the derivation report.",
    )
    commands = parser.add_subparsers(dest="command", required=True)
    for name, help_text in [
        ("generate", "run every derivation and write every generated tree and the report"),
        ("verify", "run every derivation and print one line per paper equation"),
        (
            "check",
            "regenerate under two hash seeds into a temporary folder and diff every "
            "generated tree and the report against the committed ones",
        ),
        ("report", "run every derivation and write the derivation report only"),
    ]:
        sub = commands.add_parser(name, help=help_text, description=help_text)
        sub.add_argument(
            "--derivations",
            type=Path,
            default=ROOT / "derivations",
            help="folder of derivation scripts (default: ./derivations)",
        )
        sub.add_argument(
            "--root",
            type=Path,
            default=ROOT / "generated",
            help="the generated root holding asymslip_gen/, c/, fortran/, "
            "matlab/ and report/ (default: ./generated)",
        )
        sub.add_argument("--quiet", action="store_true", help="no progress lines on stderr")
        if name in ("generate", "report"):  # check reads ROOT's committed map itself
            sub.add_argument(
                "--error-map",
                type=Path,
                default=None,
                help="the committed error map summarised in the report "
                f"(default: {REPORT_FOLDER}/{ERROR_MAP_FILE} under --root; left "
                "out if missing)",
            )
    args = parser.parse_args(argv)

    if args.command == "check":
        return check_fresh(args.derivations, args.root)
    start = time.perf_counter()
    run = run_derivations(args.derivations, progress=not args.quiet)
    if args.command == "verify":
        print_verification(run)
        print(f"total {time.perf_counter() - start:.1f} s")
        return 0
    error_map = args.error_map or args.root / REPORT_FOLDER / ERROR_MAP_FILE
    generated = render_all(
        run, error_map.read_text(encoding="utf-8") if error_map.is_file() else None
    )
    folders = [REPORT_FOLDER] if args.command == "report" else None
    count = write_generated(generated, args.root, folders)
    if not args.quiet:
        written = ", ".join(f"{folder}/" for folder in folders or generated.trees)
        print(
            f"wrote {count} files ({len(run.formulas)} functions) to {args.root}/{{{written}}} "
            f"in {time.perf_counter() - start:.1f} s",
            file=sys.stderr,
        )
    return 0


if __name__ == "__main__":
    sys.exit(main())
