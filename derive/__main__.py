"""``python -m snakecg_derive``: regenerate model folders from the derivation.

``python -m snakecg_derive --checked-in --out generated`` rewrites every checked-in model and
the package index; ``--joints N`` writes one model.
"""

from __future__ import annotations

import argparse
import sys

from .render import CHECKED_IN_JOINTS, render_model, write_index, write_model


def main(argv=None) -> int:
    p = argparse.ArgumentParser(prog="python -m snakecg_derive", description=__doc__)
    p.add_argument("--joints", type=int, action="append", help="joint count (repeatable)")
    p.add_argument("--checked-in", action="store_true",
                   help=f"all checked-in joint counts {CHECKED_IN_JOINTS} and the index")
    p.add_argument("--out", default="generated", help="output folder (default: generated)")
    a = p.parse_args(argv)
    counts = list(CHECKED_IN_JOINTS) if a.checked_in else (a.joints or [])
    if not counts:
        p.error("give --joints N or --checked-in")
    for n in counts:
        folder = write_model(render_model(n), a.out)
        print(f"wrote {folder}")
    if a.checked_in:
        print(f"wrote {write_index(a.out)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
