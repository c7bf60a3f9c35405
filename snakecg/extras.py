"""The pip command that installs one of snakecg's optional extras, for the way snakecg itself
was installed (from a package index, from a checkout, editable, or not at all)."""

from __future__ import annotations

import json

__all__ = ["install_hint"]

#: The packages of each extra (for a source tree run without installing snakecg).
PACKAGES = {"urdf": "yourdfpy", "sweep": "'dask[distributed]' zarr xxhash",
            "notebook": "ipywidgets"}


def install_hint(extra: str) -> str:
    """``pip install ...`` that adds ``extra`` to this installation of snakecg.

    From a package index: ``pip install 'snakecg[extra]'``; from a local folder (a
    checkout): ``pip install '<folder>[extra]'`` (with ``-e`` for an editable install); from
    a version-control URL: ``pip install 'snakecg[extra] @ <url>'``; snakecg not installed
    (a source tree on the path): the extra's packages themselves.
    """
    from importlib import metadata
    from urllib.parse import unquote, urlparse

    try:
        dist = metadata.distribution("snakecg")
    except metadata.PackageNotFoundError:
        return f"pip install {PACKAGES.get(extra, extra)}"
    try:
        direct = json.loads(dist.read_text("direct_url.json") or "null")
    except (OSError, ValueError):
        direct = None
    if not isinstance(direct, dict) or "url" not in direct:
        return f"pip install 'snakecg[{extra}]'"
    url = direct["url"]
    if "dir_info" in direct and url.startswith("file:"):
        folder = unquote(urlparse(url).path)
        editable = "-e " if direct["dir_info"].get("editable") else ""
        return f"pip install {editable}'{folder}[{extra}]'"
    if "vcs_info" in direct:
        return f"pip install 'snakecg[{extra}] @ {direct['vcs_info'].get('vcs', 'git')}+{url}'"
    return f"pip install {PACKAGES.get(extra, extra)}"
