"""``python -m snakecg_derive.spatial``: regenerate spatial model folders.

``--checked-in`` rewrites every checked-in spatial model under ``generated/spatial/``;
``--links N`` writes one model into ``--out``.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from .catalog import CHECKED_IN_SPATIAL_JOINTS
from .render import render_spatial_model, write_spatial_model


def main(argv=None) -> int:
    p = argparse.ArgumentParser(prog="python -m snakecg_derive.spatial", description=__doc__)
    p.add_argument("--links", type=int, action="append", help="link count (repeatable)")
    p.add_argument("--checked-in", action="store_true",
                   help="every checked-in spatial model (joints "
                        f"{', '.join(map(str, CHECKED_IN_SPATIAL_JOINTS))})")
    p.add_argument("--out", default=None,
                   help="output folder (default: generated/spatial)")
    a = p.parse_args(argv)
    counts = [n + 1 for n in CHECKED_IN_SPATIAL_JOINTS] if a.checked_in else (a.links or [])
    if not counts:
        p.error("give --links N or --checked-in")
    out = Path(a.out) if a.out else Path("generated") / "spatial"
    for n in counts:
        print(f"wrote {write_spatial_model(render_spatial_model(n), out)}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
