"""``python -m asymslip.codegen {generate,verify,check,report}``: the Makefile's entry points."""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

from .report import REPORT_PATH, render_report
from .runner import (
    check_figure_data,
    check_fresh,
    print_verification,
    render_package,
    run_derivations,
    write_package,
    write_report,
)

ROOT = Path.cwd()


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        prog="python -m asymslip.codegen",
        description="Run the SymPy derivations and write, verify or freshness-check the "
        "generated asymslip_gen package.",
    )
    commands = parser.add_subparsers(dest="command", required=True)
    for name, help_text in [
        ("generate", "run every derivation and write generated/asymslip_gen"),
        ("verify", "run every derivation and print one line per paper equation"),
        ("check", "regenerate into a temporary folder and diff against the committed package "
         "and report"),
        ("report", "run every derivation and write the derivation report (Markdown)"),
    ]:
        sub = commands.add_parser(name, help=help_text, description=help_text)
        sub.add_argument("--derivations", type=Path, default=ROOT / "derivations",
                         help="folder of derivation scripts (default: ./derivations)")
        sub.add_argument("--out", type=Path, default=ROOT / "generated" / "asymslip_gen",
                         help="generated package folder (default: ./generated/asymslip_gen)")
        sub.add_argument("--quiet", action="store_true", help="no progress lines on stderr")
        if name != "verify":
            # generate writes the report only when asked (so `generate --out tmp` touches
            # nothing else); report and check default to the committed report.
            default = None if name == "generate" else ROOT / REPORT_PATH
            sub.add_argument("--report", type=Path, default=default,
                             help=f"derivation report (report/check default: ./{REPORT_PATH})")
    args = parser.parse_args(argv)

    if args.command == "check":
        status = check_fresh(args.derivations, args.out, report=args.report)
        # The figure data come from the committed package: compare them only once it is fresh.
        return status or check_figure_data(ROOT / "generated" / "figures")
    start = time.perf_counter()
    run = run_derivations(args.derivations, progress=not args.quiet)
    if args.command != "verify" and args.report is not None:
        write_report(render_report(run), args.report)
        if not args.quiet:
            print(f"wrote {args.report}", file=sys.stderr)
    if args.command == "generate":
        files = render_package(run)
        write_package(files, args.out)
        if not args.quiet:
            print(
                f"wrote {len(files)} files, {len(run.formulas)} functions to {args.out} "
                f"in {time.perf_counter() - start:.1f} s",
                file=sys.stderr,
            )
    elif args.command == "verify":
        print_verification(run)
        print(f"total {time.perf_counter() - start:.1f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
