"""Where a sweep runs (snakecg/sweeps/cluster.py): the local cluster admits no one but the
sweep, and --scheduler keeps its 10 s limit against listeners that are not Dask schedulers.

The attacks are real connections on the loopback interface: a plain-TCP Dask client and a
TLS client with other credentials against the cluster `snakecg.sweep` starts (each tries to
run a task that writes a file), and fake listeners (silent, an HTTP server, a scheduler
without workers) against `snakecg sweep --scheduler`.
"""

from __future__ import annotations

import socket
import subprocess
import sys
import textwrap
import threading
import time
from pathlib import Path

import distributed
import pytest

from snakecg.cli import main

ROOT = Path(__file__).resolve().parents[1]

INTRUDER = textwrap.dedent("""
    import sys, distributed
    from distributed.security import Security
    address, marker, how = sys.argv[1:]
    security = Security.temporary() if how == "other-credentials" else None
    def touch(path):
        open(path, "w").write("ran")
        return 1
    try:
        c = distributed.Client(address, timeout=5, security=security)
        c.submit(touch, marker, pure=False).result(timeout=10)
    except BaseException as exc:
        print("refused:", type(exc).__name__)
        sys.exit(3)
    print("submitted")
""")


def _intrude(address: str, marker: Path, how: str) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-c", INTRUDER, address, str(marker), how],
                          capture_output=True, text=True, timeout=120, cwd=ROOT, check=False)


def test_no_other_client_can_submit_work_to_the_local_cluster(tmp_path):
    """The cluster snakecg.sweep starts listens with TLS only and admits the holders of its
    temporary credentials: a plain tcp:// client, and a tls:// client with other
    credentials, can neither connect to its scheduler nor run a task; the sweep's own client
    can (the control). The workers' and nannies' listeners are TLS too."""
    from snakecg.sweeps.cluster import connect

    c, close = connect(workers=1)
    try:
        address = c.scheduler.address
        assert address.startswith("tls://127.0.0.1:")
        workers = c.scheduler_info()["workers"]
        nannies = [w["nanny"] for w in workers.values()]
        assert all(a.startswith("tls://") for a in [*workers, *nannies])
        plain = "tcp://" + address.split("://", 1)[1]
        for how, target in (("plain", plain), ("other-credentials", address)):
            marker = tmp_path / f"intruder-{how}"
            res = _intrude(target, marker, how)
            assert res.returncode == 3 and "refused" in res.stdout, (how, res.stdout,
                                                                     res.stderr[-2000:])
            assert not marker.exists(), how
        # a worker's own listener, addressed directly over plain TCP
        marker = tmp_path / "intruder-worker"
        res = _intrude("tcp://" + next(iter(workers)).split("://", 1)[1], marker, "plain")
        assert res.returncode == 3 and not marker.exists(), res.stdout
        # the control: the sweep's client runs a task
        own = tmp_path / "own"
        assert c.submit(lambda p: Path(p).write_text("ran"), str(own), pure=False).result()
        assert own.read_text() == "ran"
    finally:
        close()


# ------------------------------------------------------------------------------------------
class FakeListener:
    """A TCP listener on 127.0.0.1 that accepts and then stays silent (``"silent"``),
    answers a request with an HTTP error (``"http"``), or greets first with a line of text
    (``"banner"``, as SSH and mail servers do); bounded: it serves at most 20 connections and
    stops when closed."""

    def __init__(self, kind: str):
        self.kind = kind
        self.sock = socket.socket()
        self.sock.bind(("127.0.0.1", 0))
        self.sock.listen(8)
        self.sock.settimeout(0.2)
        self.port = self.sock.getsockname()[1]
        self.open = []
        self.stop = threading.Event()
        self.thread = threading.Thread(target=self._serve, daemon=True)
        self.thread.start()

    def _serve(self):
        for _ in range(20):
            while not self.stop.is_set():
                try:
                    conn, _ = self.sock.accept()
                    break
                except TimeoutError:
                    continue
            else:
                return
            self.open.append(conn)
            if self.kind == "banner":
                conn.sendall(b"SSH-2.0-OpenSSH_9.2p1 Debian-2\r\n" + b"x" * 64)
            if self.kind == "http":
                conn.settimeout(2)
                try:
                    conn.recv(1024)
                except OSError:
                    pass
                conn.sendall(b"HTTP/1.1 400 Bad Request\r\nContent-Length: 0\r\n\r\n")

    def close(self):
        self.stop.set()
        self.thread.join(timeout=5)
        for c in self.open:
            c.close()
        self.sock.close()


def _run_cli(capsys, argv):
    t = time.monotonic()
    code = main(argv)
    return code, capsys.readouterr().err, time.monotonic() - t


@pytest.mark.parametrize("kind,fragment", [
    ("silent", ("no Dask scheduler answered at",)),
    # The HTTP server replies once it has read the probe or its own 2 s limit runs out,
    # whichever comes first: either refusal names the address and is right.
    ("http", ("no Dask scheduler answered at", "is not a Dask scheduler")),
    ("banner", ("is not a Dask scheduler",))])
def test_scheduler_that_is_not_a_dask_scheduler_is_refused_in_time(tmp_path, capsys,
                                                                   monkeypatch, kind,
                                                                   fragment):
    """A listener that never answers, an HTTP server (the issue's: Dask read its reply as the
    length of a message of exabytes), or a server that greets with text, is refused on one
    line (exit 2) within the connection limit (here 2 s), and nothing is written."""
    from snakecg.sweeps import cluster

    monkeypatch.setattr(cluster, "CONNECT_TIMEOUT", 2.0)
    fake = FakeListener(kind)
    result = {}
    store = tmp_path / "s.zarr"

    def run():
        result["v"] = _run_cli(capsys, ["sweep", "--joints", "2", "--out", str(store),
                                        "--scheduler", f"tcp://127.0.0.1:{fake.port}"])

    t = threading.Thread(target=run, daemon=True)
    t.start()
    t.join(timeout=60)
    fake.close()
    assert not t.is_alive(), "the sweep hangs on a listener that does not answer"
    code, err, seconds = result["v"]
    assert code == 2 and err.count("\n") == 1, err
    assert any(f in err for f in fragment) and f"127.0.0.1:{fake.port}" in err, err
    assert "Traceback" not in err and seconds < 30
    assert not store.exists()


def test_scheduler_without_workers_is_a_one_line_failure(tmp_path, capsys, monkeypatch):
    """A real scheduler with no worker: the sweep does not wait silently; after the limit
    it fails on one line (exit 1: nothing is wrong with the input) naming the way out."""
    from snakecg.sweeps import cluster

    monkeypatch.setattr(cluster, "CONNECT_TIMEOUT", 2.0)
    with distributed.LocalCluster(n_workers=0, processes=False, protocol="tcp://",
                                  host="127.0.0.1", dashboard_address=None) as empty:
        code, err, seconds = _run_cli(capsys, ["sweep", "--joints", "2", "--out",
                                               str(tmp_path / "s.zarr"), "--scheduler",
                                               empty.scheduler_address])
    assert code == 1 and err.count("\n") == 1 and "has no workers" in err, err
    assert "dask worker" in err and seconds < 30
