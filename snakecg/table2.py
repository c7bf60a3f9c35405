"""Table 2 of Reyes & Ma 2017 (case study 2): the published values, the reproduced entries,
which shapes attain them, and the table as text, Markdown and CSV.

An entry is the worst (least) or best (largest) over the grid's configurations of the
per-configuration maximum of ``norm_a_obj`` or ``sr``. Every entry attained by a shape that
is not physically possible carries :data:`snakecg.geometry.INFEASIBLE_MARK` (``*``), as
``snakecg sweep --summary`` marks its entries and Fig. 6 frames those shapes in red; beside
it, the same entry over the physically possible shapes only. The caption
(:data:`A_OBJ_CAPTION`) says why the paper's ``||a_obj||^2`` rows are not reproducible from
its Table 1.
"""

from __future__ import annotations

import csv
import io

import numpy as np

from .geometry import INFEASIBLE_MARK, SELF_CLEARANCE, infeasible_footnote
from .robot import SCENARIOS

__all__ = ["PAPER_TABLE2", "TABLE2_ROWS", "SCENARIO_LABEL", "A_OBJ_CAPTION", "table2",
           "table2_index", "table2_text"]

#: Table 2 of Reyes & Ma 2017 (case study 2): scenario 1, 2, 3.
PAPER_TABLE2 = {
    "worst_norm_a_obj": (0.000763215, 0.00107454, 0.00107454),
    "best_norm_a_obj": (0.00785302, 0.00861168, 0.00861168),
    "worst_sr": (0.00138484, 0.00185713, 0.00185098),
    "best_sr": (0.0267348, 0.988638, 0.988643),
}
TABLE2_ROWS = {
    "worst_norm_a_obj": "Worst ||a_obj||^2",
    "best_norm_a_obj": "Best ||a_obj||^2",
    "worst_sr": "Worst sr",
    "best_sr": "Best sr",
}
SCENARIO_LABEL = {"frictionless": "Scenario 1 (frictionless)",
                  "wheels": "Scenario 2 (wheels, mu = 0.1)",
                  "ideal_wheels": "Scenario 3 (ideal wheels)"}
#: Why the ||a_obj||^2 rows differ from the paper's (docs/how-to/reproduction.md has the numbers).
A_OBJ_CAPTION = (
    "The paper's ||a_obj||^2 rows are not reproducible from its Table 1: they scale with the "
    "input region (31), whose printed form tau^T Mbar_s^-1 tau does not type-check, and with "
    "how the maximum over it was taken, which the paper does not state. The sr rows, which "
    "depend on neither (sr is homogeneous of degree 0 in tau), come within 1.6 % (best) and "
    "13 % (worst). Here ||a_obj||^2 is "
    "the exact maximum over tau^T B^T M_s^-1 B tau <= 1, 9 to 77 % above the paper's; the "
    "other readings tried (the inverse of M_s's joint block, the unit sphere) give 4 to 550 "
    "times the paper's values, and no "
    "sampling of the torques tried (12 directions; box grids of 3 to 21 points per axis) "
    "gives the four ||a_obj||^2 entries together (snakecg reproduce --alternatives).")


def table2(results, mask=None) -> dict:
    """Table 2 from per-configuration maxima: worst = min over configurations, best = max
    (over the configurations where ``mask`` is true, when given). ``results[scenario]`` is
    ``(model, extremes, radius, angle)``."""
    idx = table2_index(results, mask)
    return {key: tuple(float(results[s][1].max[key.split("_", 1)[1]][idx[key][j]])
                       for j, s in enumerate(SCENARIOS))
            for key in PAPER_TABLE2}


def table2_index(results, mask=None) -> dict:
    """Index of the configuration attaining each Table 2 entry, per scenario (among those
    where ``mask`` is true, when given)."""
    idx = {}
    for key in PAPER_TABLE2:
        kind, metric = key.split("_", 1)
        per = []
        for s in SCENARIOS:
            v = np.asarray(results[s][1].max[metric], float)
            if mask is not None:
                v = np.where(mask, v, np.inf if kind == "worst" else -np.inf)
            per.append(int(np.argmin(v) if kind == "worst" else np.argmax(v)))
        idx[key] = tuple(per)
    return idx


def table2_text(t: dict, *, feasible: dict | None = None, feasible_only: dict | None = None,
                clearance: float = SELF_CLEARANCE) -> tuple[str, str, str]:
    """(terminal text, Markdown, CSV) of Table 2 ``t`` beside the paper's values.

    ``feasible[key][j]``: whether the shape attaining entry ``t[key][j]`` is physically
    possible (False: the entry is marked ``*``); ``feasible_only[key][j]``: the entry over
    the physically possible shapes only (a column beside each entry). Either may be None
    (unknown: no mark, no column)."""
    def mark(key, j):
        return "" if feasible is None or feasible[key][j] else INFEASIBLE_MARK

    extra = feasible_only is not None
    md = ["| Concept | " + " | ".join(
        f"{SCENARIO_LABEL[s]}: snakecg | paper | rel. diff." + (" | feasible only" if extra
                                                                  else "")
        for s in SCENARIOS) + " |",
          "|---|" + ("---|---|---|" + ("---|" if extra else "")) * 3]
    head = ["concept", "scenario", "snakecg", "paper", "relative_difference"]
    if feasible is not None:
        head.append("shape_feasible")
    if extra:
        head.append("feasible_only")
    rows_csv = [head]
    width = 48 if extra else 36
    term = [f"{'Table 2':<20}" + "".join(f"{s:>{width}}" for s in SCENARIOS),
            f"{'':<20}" + "".join(f"{'snakecg':>12}{'paper':>12}{'rel.diff':>12}"
                                  + (f"{'feas. only':>12}" if extra else "")
                                  for _ in SCENARIOS)]
    for key, label in TABLE2_ROWS.items():
        cells, tline = [], f"{label:<20}"
        for j, s in enumerate(SCENARIOS):
            ours, paper = t[key][j], PAPER_TABLE2[key][j]
            rel = (ours - paper) / paper
            m = mark(key, j)
            cell = f"{ours:.6g}{m and chr(92) + m} | {paper:.6g} | {rel:+.1%}"  # \* in Markdown
            tline += f"{f'{ours:.6g}{m}':>12}{paper:>12.6g}{rel:>+12.1%}"
            row = [key, s, f"{ours:.9g}", f"{paper:.9g}", f"{rel:.6f}"]
            if feasible is not None:
                row.append("true" if feasible[key][j] else "false")
            if extra:
                cell += f" | {feasible_only[key][j]:.6g}"
                tline += f"{feasible_only[key][j]:>12.6g}"
                row.append(f"{feasible_only[key][j]:.9g}")
            cells.append(cell)
            rows_csv.append(row)
        md_label = label.replace("||", "‖").replace("^2", "²")  # no "|" inside a table cell
        md.append(f"| {md_label} | " + " | ".join(cells) + " |")
        term.append(tline)
    notes = []
    if feasible is not None and not all(all(v) for v in feasible.values()):
        notes.append(infeasible_footnote(clearance))
    if extra:
        notes.append("feasible only: the entry over the physically possible shapes alone")
    caption = A_OBJ_CAPTION
    md_notes = [n.replace(INFEASIBLE_MARK, "\\" + INFEASIBLE_MARK, 1) if
                n.startswith(INFEASIBLE_MARK) else n for n in notes]
    md_text = ("\n".join(md) + "\n\n" + "".join(f"{n}.  \n" for n in md_notes)
               + "\n" + caption.replace("||", "‖").replace("^2", "²") + "\n")
    buf = io.StringIO()
    csv.writer(buf, lineterminator="\n").writerows(rows_csv)
    term_text = "\n".join(term + [f"{n}." for n in notes] + [_wrap(caption, 100)])
    return term_text, md_text, buf.getvalue()


def _wrap(text: str, width: int) -> str:
    import textwrap

    return "\n".join(textwrap.wrap(text, width))
