"""Symbolic inspection: the closed forms behind the generated code, by name, and their
display (never used by the generation path).

Names (``n`` = joint count): ``M`` (eq. 4, in absolute link angles), ``M_expanded``
(eq. 4 written out as ``sum J_i^T D_i J_i``), ``J1`` .. ``J<n+1>`` (eq. 3), ``h`` (eq. 4),
``K`` (derived parameters), ``contact`` (link-level contact row: ``a_link``, ``G^T`` row and
``Adot v``), ``contact<k>`` (the contact row ``-J_s`` on link ``k``, eq. 10, in ``q``),
``wheel<i>`` (the wheel row of link ``i`` in ``q``, and its ``Adot v``).

* :func:`expression`: the SymPy objects; :func:`substitute` puts numbers (or expressions) in
  by the symbols' names, so a plain ``sympy.Symbol("q1")`` or ``"q1"`` works although the
  derivation's symbols carry assumptions (``real=True``, ``positive=True``) and a plain
  symbol is a different one to SymPy; a name the expression does not have is refused.
* :func:`simplified`: ``trigsimp`` and collection on each entry, for display
  (``c3 sin^2 + c3 cos^2 -> c3``).
* :func:`latex_block`: one ``aligned`` block for one equation environment: one line per
  entry (``M_{12} &= ...``, zero entries left out, a symmetric matrix's upper triangle),
  long entries broken after top-level sums so that no line is wider than a page, each part
  introduced by a ``%`` comment, no blank line.
"""

from __future__ import annotations

import re

import sympy as sp

from .constraints import ContactSymbols, contact_row_local, wheel_row_local
from .kinematics import (
    StructuredChain,
    closed_form_jacobians,
    closed_form_mass_matrix,
    closed_form_poses,
    derived_parameter_values,
    readable_mass_matrix,
)
from .symbols import SnakeSymbols

__all__ = ["expression", "names", "substitute", "simplified", "latex_symbol_names",
           "latex_block", "LATEX_WIDTH"]

#: Longest line of :func:`latex_block`, in characters of LaTeX source: a line this long
#: typesets narrower than the 16 cm text width of an A4 page at 10 pt.
LATEX_WIDTH = 90


def names(n_joints: int) -> list[str]:
    nl = n_joints + 1
    return (["M", "M_expanded", "h", "K", "contact"] + [f"J{i}" for i in range(1, nl + 1)]
            + [f"contact{k}" for k in range(1, nl + 1)] + [f"wheel{i}" for i in range(1, nl + 1)])


def _link_subs(s: SnakeSymbols, i: int) -> dict:
    """Link-level symbols of link ``i`` in terms of ``q`` and ``v`` (closed form)."""
    C = ContactSymbols
    pose = closed_form_poses(s)[i - 1]
    J = closed_form_jacobians(s)[i - 1]
    v = sp.Matrix(s.v)
    twist = J * v
    bias = (J * v).jacobian(sp.Matrix(s.q)) * v
    subs = dict(zip(C.link_pose, pose))
    subs.update(dict(zip(C.link_twist, twist)))
    subs.update(dict(zip(C.link_bias, bias)))
    subs[C.link_com] = s.link_com[i - 1]
    return subs


def expression(n_joints: int, what: str) -> dict[str, sp.Expr | sp.Matrix]:
    """The named closed form(s) for a snake with ``n_joints`` joints: ``{label: expression}``."""
    s = SnakeSymbols(n_joints)
    nl = s.n_links
    if what == "M":
        return {"M_s (eq. 4)": readable_mass_matrix(s)}
    if what == "M_expanded":
        return {"M_s = sum_i J_i^T diag(m_i, m_i, I_i) J_i (eq. 4)": closed_form_mass_matrix(s)}
    if what == "h":
        ch = StructuredChain(s)
        h = ch.bias_forces()
        subs = {}
        for sym, expr in ch.assignments:
            subs[sym] = expr.xreplace(subs)
        h = h.xreplace(subs).xreplace(derived_parameter_values(s))
        return {"h_s (eq. 4)": h.applyfunc(sp.expand)}
    if what == "K":
        dp = derived_parameter_values(s)
        return {str(k): v for k, v in dp.items()}
    if what == "contact":
        cr = contact_row_local()
        return {"a_link": cr["a_link"], "G^T row": cr["g_obj"], "Adot v": cr["adot_v"],
                "gap": cr["gap"], "s": cr["s"]}
    m = re.fullmatch(r"(J|contact|wheel)(\d+)", what)
    if m and 1 <= int(m.group(2)) <= nl:
        kind, i = m.group(1), int(m.group(2))
        if kind == "J":
            return {f"J_{i} (eq. 3)": closed_form_jacobians(s)[i - 1]}
        subs = _link_subs(s, i)
        J = closed_form_jacobians(s)[i - 1]
        if kind == "contact":
            cr = contact_row_local()
            a = cr["a_link"].xreplace(subs)
            return {f"-J_s row, contact on link {i} (eq. 10)": (a * J).applyfunc(sp.expand),
                    "G^T row (eq. 9)": cr["g_obj"].xreplace(subs)}
        wr = wheel_row_local()
        a = wr["a_w"].xreplace(subs)
        return {f"A row, wheel on link {i}": (a * J).applyfunc(sp.expand),
                "Adot v (eq. 13)": sp.expand(wr["adot_v"].xreplace(subs))}
    raise ValueError(
        f"unknown expression {what!r} for {n_joints} joints; choose one of: "
        + ", ".join(names(n_joints))
    )



# ------------------------------------------------------------------------------------------
# numbers in by name
# ------------------------------------------------------------------------------------------
def substitute(e, values: dict):
    """``e`` with ``values`` substituted, keys matched to ``e``'s symbols by *name*: a key may
    be a name (``"q1"``) or any SymPy symbol of that name, whatever its assumptions (a plain
    ``sympy.Symbol("q1")`` is not the derivation's ``Symbol("q1", real=True)``, and
    ``e.subs`` would silently leave it alone). A name that ``e`` does not have is refused
    with a ``ValueError`` listing the names it has."""
    free = e.free_symbols if isinstance(e, (sp.Basic, sp.MatrixBase)) else set()
    by_name = {s.name: s for s in free}
    mapping, unknown = {}, []
    for key, value in values.items():
        name = key if isinstance(key, str) else getattr(key, "name", None)
        if name is None:
            raise ValueError(f"substitute: keys must be symbol names or SymPy symbols, got "
                             f"{key!r}")
        if name not in by_name:
            unknown.append(name)
        else:
            mapping[by_name[name]] = value
    if unknown:
        raise ValueError(f"substitute: {', '.join(sorted(unknown))} is not a symbol of this "
                         f"expression; its symbols: {', '.join(sorted(by_name))}")
    return e.xreplace({k: sp.sympify(v) for k, v in mapping.items()})


# ------------------------------------------------------------------------------------------
# display
# ------------------------------------------------------------------------------------------
def _simplify_entry(x):
    if not isinstance(x, sp.Basic) or x.is_number:
        return x
    x = sp.trigsimp(x)
    trig = sorted(x.atoms(sp.sin, sp.cos), key=sp.default_sort_key)
    speeds = sorted((s for s in x.free_symbols if s.name.endswith("d") or
                     re.fullmatch(r"qd\d+", s.name)), key=sp.default_sort_key)
    return sp.collect(sp.expand(x), speeds + trig) if trig or speeds else x


def simplified(e):
    """``trigsimp`` then collection by the velocities and the sines and cosines, entry by
    entry (display only: seconds for 2 joints, up to minutes at 6-8)."""
    if isinstance(e, sp.MatrixBase):
        return e.applyfunc(_simplify_entry)
    return _simplify_entry(e)


_LATEX_PATTERNS = [
    (re.compile(r"mtot"), lambda m: r"m_{\mathrm{tot}}"),
    (re.compile(r"beta(\d+)"), lambda m: rf"\beta_{{{m[1]}}}"),
    (re.compile(r"gamma(\d+)_(\d+)"), lambda m: rf"\gamma_{{{m[1]}{m[2]}}}"),
    (re.compile(r"Jrot(\d+)"), lambda m: rf"J^{{\mathrm{{rot}}}}_{{{m[1]}}}"),
    (re.compile(r"(x|y)d"), lambda m: rf"\dot{{{m[1]}}}"),
    (re.compile(r"thetad"), lambda m: r"\dot{\theta}"),
    (re.compile(r"qd(\d+)"), lambda m: rf"\dot{{q}}_{{{m[1]}}}"),
    (re.compile(r"l(x|y)"), lambda m: rf"{m[1]}_{{\ell}}"),
    (re.compile(r"lphi"), lambda m: r"\phi_{\ell}"),
    (re.compile(r"lv(x|y)"), lambda m: rf"v_{{\ell {m[1]}}}"),
    (re.compile(r"lw"), lambda m: r"\omega_{\ell}"),
    (re.compile(r"lb(x|y)"), lambda m: rf"b_{{\ell {m[1]}}}"),
    (re.compile(r"lbw"), lambda m: r"b_{\ell \omega}"),
    (re.compile(r"lc"), lambda m: r"c_{\ell}"),
    (re.compile(r"o(x|y)"), lambda m: rf"{m[1]}_{{o}}"),
    (re.compile(r"opsi"), lambda m: r"\psi"),
    (re.compile(r"ov(x|y)"), lambda m: rf"v_{{o {m[1]}}}"),
    (re.compile(r"ow"), lambda m: r"\omega_{o}"),
    (re.compile(r"rho(x|y)"), lambda m: rf"\rho_{{{m[1]}}}"),
    (re.compile(r"woff"), lambda m: r"w_{\mathrm{off}}"),
]


def latex_symbol_names(*exprs) -> dict:
    """LaTeX names of the derivation's symbols in ``exprs`` (for ``sympy.latex``).

    ``mtot -> m_tot``, ``beta1 -> beta_1``, ``gamma1_2 -> gamma_12``, ``Jrot1 -> J^rot_1``,
    velocities ``thetad -> dot theta``, link-level symbols ``lx, lphi, lvx, lw, lbx, lc -> x_l,
    phi_l, v_lx, omega_l, b_lx, c_l``, object ``ox, opsi, ovx, ow -> x_o, psi, v_ox,
    omega_o``, ``rhox -> rho_x``, ``woff -> w_off``. Other symbols keep SymPy's names.
    """
    out = {}
    for e in exprs:
        syms = e.free_symbols if isinstance(e, (sp.Basic, sp.MatrixBase)) else set()
        for s in syms:
            for pat, fmt in _LATEX_PATTERNS:
                m = pat.fullmatch(s.name)
                if m:
                    out[s] = fmt(m)
                    break
    return out


#: The LaTeX name of an expression's label's first word (the rest is the comment).
_LABEL_NAMES = {"M_s": "M", "M_s =": "M", "h_s": "h", "-J_s": r"\left(-J_s\right)",
                "G^T": r"G^{\mathsf{T}}", "A": "A", "Adot": r"\dot{A} v", "a_link":
                r"a_{\ell}", "gap": "g", "s": "s"}


def _name(label: str) -> str:
    head = label.split(" ")[0]
    if label.startswith("M_s"):
        return "M"
    if head in _LABEL_NAMES:
        return _LABEL_NAMES[head]
    m = re.fullmatch(r"J_(\d+)", head)
    if m:
        return rf"\left(J_{{{m[1]}}}\right)"
    return sp.latex(sp.Symbol(head), symbol_names=latex_symbol_names(sp.Symbol(head))) \
        if re.fullmatch(r"[A-Za-z]+\d*(_\d+)?", head) else rf"\text{{{head}}}"


def _split(lhs: str, e, names: dict, width: int) -> list[str]:
    r"""``lhs &= e`` as lines no wider than ``width`` where the terms of a top-level sum
    allow; a term too long for a line that is a product with a sum as a factor
    (``qd1^2 (a + b + ...)``) has its sum broken the same way inside ``\Bigl( ... \Bigr)``
    (which, unlike ``\left( ... \right)``, may span lines), and so on inside it, each level
    indented further. Other terms are never cut."""
    def tex(x):
        return sp.latex(x, symbol_names=names)

    lines = [f"{lhs} &="]
    starts = ("&=", f"{lhs} &=")

    def add(piece: str, depth: int) -> None:
        if len(lines[-1]) + len(piece) > width and not (
                lines[-1].strip() in starts or lines[-1].strip().startswith("&\\q")
                and lines[-1].strip().count(" ") == 0):
            lines.append("  &" + r"\quad" * (depth + 1))
        lines[-1] += piece

    def emit(terms, depth: int, opening: str = "") -> None:
        for k, t in enumerate(terms):
            neg = k > 0 and t.could_extract_minus_sign()
            body = -t if neg else t
            sign = (" - " if neg else " + ") if k else " "
            if k == 0 and opening:  # a bracket opens on the line of its first term
                sign = opening + sign
            piece = sign + tex(body)
            inner = ([f for f in body.args if isinstance(f, sp.Add)]
                     if isinstance(body, sp.Mul) else [])
            if len(piece) <= width - 8 * (depth + 1) or len(inner) != 1 or depth >= 3:
                add(piece, depth - 1 if k == 0 and opening else depth)
                continue
            factors = body.as_ordered_factors()  # the printer's order, around the sum
            at = factors.index(inner[0])
            before, after = factors[:at], factors[at + 1:]
            head = ""
            if before and before[0] == -1:
                head, before = "- ", before[1:]
            if before:
                head += tex(sp.Mul(*before, evaluate=False)) + " "
            big = (r"\Bigl(", r"\Bigr)") if depth == 0 else (r"\bigl(", r"\bigr)")
            emit(inner[0].as_ordered_terms(), depth + 1, sign + head + big[0])
            lines[-1] += " " + big[1] + ("" if not after else
                                         " " + tex(sp.Mul(*after, evaluate=False)))

    emit(e.as_ordered_terms() if isinstance(e, sp.Add) else [e], 0)
    return lines


def latex_block(exprs: dict, *, width: int = LATEX_WIDTH, simplify: bool = False) -> str:
    """The expressions ``{label: expr}`` of :func:`expression` as one ``aligned`` block (see
    the module doc): paste it into one ``equation`` (or ``\\[ ... \\]``) environment.
    ``simplify``: :func:`simplified` first."""
    names = latex_symbol_names(*exprs.values())
    lines = [r"\begin{aligned}"]
    body = []
    for label, e in exprs.items():
        e = simplified(e) if simplify else e
        name = _name(label)
        if isinstance(e, sp.MatrixBase):
            rows, cols = e.shape
            symmetric = rows == cols and rows > 1 and e == e.T
            vector = 1 in (rows, cols)
            entries = [(i, j) for i in range(rows) for j in range(i if symmetric else 0, cols)
                       if e[i, j] != 0]
            shape = f"{rows} x {cols}" + (", symmetric: upper triangle" if symmetric else "")
            body.append([f"% {label}: {shape}, zero entries left out"])
            for i, j in entries:
                k = (i if cols == 1 else j) + 1
                sub = f"{k}" if vector else (f"{i + 1}{j + 1}" if max(rows, cols) < 10
                                            else f"{i + 1},{j + 1}")
                base = f"{{{name}}}" if re.search(r"[_^]", name) else name  # no x_a_b
                body[-1].extend(_split(f"{base}_{{{sub}}}", e[i, j], names, width))
            if not entries:
                body[-1].append(f"{name} &= 0")
        else:
            plain = re.fullmatch(r"[A-Za-z]+\d*(_\d+)?", label)  # a constant's own name
            body.append(([] if plain else [f"% {label}"]) + _split(name, e, names, width))
    flat = [ln for part in body for ln in part]
    eq = [k for k, ln in enumerate(flat) if not ln.startswith("%")]
    for k in eq[:-1]:  # every equation line but the last ends the row
        flat[k] += r" \\"
    return "\n".join(lines + flat + [r"\end{aligned}"])
