# GENERATED FILE - DO NOT EDIT. Rendered from derive/templates/index.py.j2.
# Regenerate with: python -m snakecg_derive --checked-in
"""Generated models of snakecg (package ``snakecg_generated``, folder ``generated/``).

One folder per joint count, ``na<N>/``, each with ``model.py`` (builds the CasADi functions),
``c/<function>.c`` (CasADi's C plus batched drivers) and ``manifest.json`` (argument order, sizes,
hashes). Written by ``snakecg_derive``; the runtime loads them and never edits them.
"""

#: Joint counts whose models ship with the package.
CHECKED_IN_JOINTS = (1, 2, 3, 4, 5, 6,)
