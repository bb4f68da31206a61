"""Command line: ``ringchain <subcommand>``.

``ringchain paper`` is the README's main job: it derives the theory and prints the
paper's key numbers.
"""

from __future__ import annotations

import argparse
import sys

__all__ = ["main"]


def _paper(args) -> int:
    from ringchain.theory import Ring, si_to_n_per_mm

    print("Static theory of one contact (paper Sec. II, Eqs. 1-4); stainless steel, r = 2.5 mm")
    print(f"{'R/r':>5} {'K_c (N/m^1.5)':>14} {'K_b (N/m)':>11} {'F* (N)':>9} {'K (N/mm^n)':>11} {'n':>6}")
    for aspect in (3.1, 4.0, 5.5, 6.0, 9.0, 10.0):
        ring = Ring.from_aspect_ratio(aspect)
        K, n = ring.power_law()
        print(
            f"{aspect:5.1f} {ring.K_c:14.4e} {ring.K_b:11.4e} {ring.crossover_force:9.4g} "
            f"{float(si_to_n_per_mm(K, n)):11.4g} {n:6.3f}"
        )
    return 0


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="ringchain", description=__doc__.splitlines()[0])
    sub = parser.add_subparsers(dest="command", required=True)
    paper = sub.add_parser("paper", help="derive the theory and print the paper's key numbers")
    paper.set_defaults(func=_paper)
    return parser


def main(argv=None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    return args.func(args)


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
