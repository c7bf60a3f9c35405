"""Dask plumbing of a sweep: the client (a local cluster, an address or a given client) and
the progress display (Dask's progress bar on a terminal, one line per tenth otherwise)."""

from __future__ import annotations

import logging
import os
import sys
import time

from ..errors import InputError, SnakecgError

__all__ = ["connect", "ProgressLines", "start_bar", "end_bar", "progress_mode", "is_local",
           "concurrency", "fills_machine"]

#: Seconds to wait for an existing scheduler before giving up.
CONNECT_TIMEOUT = 10.0


def _distributed():
    try:
        import distributed
    except ModuleNotFoundError:
        raise InputError("sweeps need the sweep extra (Dask, Zarr and xxhash): "
                         "pip install 'snakecg[sweep]'") from None
    return distributed


def check_scheduler(address) -> str:
    """Validate a scheduler address (``tcp://HOST:PORT``) before connecting. Only plain TCP
    is taken: a ``tls://`` scheduler needs the cluster's certificates (connect a
    ``distributed.Client`` with its ``Security`` and pass it as ``client=``), and other
    transports are not for clusters of separate machines."""
    _distributed()
    from distributed.comm.addressing import parse_address, parse_host_port

    if not isinstance(address, str) or not address.strip():
        raise InputError(f"scheduler must be an address like tcp://HOST:PORT, got {address!r}")
    address = address.strip()
    scheme, loc = parse_address(address)
    if scheme == "tls":
        raise InputError(f"scheduler {address!r}: a tls:// scheduler needs its cluster's "
                         f"certificates, which --scheduler does not take; from Python, "
                         f"connect distributed.Client(address, security=...) and pass it as "
                         f"client=")
    if scheme != "tcp":
        raise InputError(f"unknown scheduler {address!r}: the scheme {scheme!r} is not "
                         f"taken; give an address like tcp://HOST:PORT")
    try:
        host, port = parse_host_port(loc)
    except (ValueError, TypeError):
        host, port = None, None
    if not host or not isinstance(port, int) or not 0 < port < 65536:
        raise InputError(f"scheduler {address!r} needs a host and a port: tcp://HOST:PORT")
    return address


def check_workers(workers) -> int:
    if workers is None:
        return os.cpu_count() or 1
    most = MAX_WORKERS_PER_CORE * (os.cpu_count() or 1)
    if isinstance(workers, bool) or not isinstance(workers, int) or not 1 <= workers <= most:
        raise InputError(f"workers must be an integer from 1 to {most} (local worker "
                         f"processes, at most {MAX_WORKERS_PER_CORE} per core of this "
                         f"machine), got {workers!r}")
    return workers


#: Local worker processes per core at most (more only share the cores and the memory).
MAX_WORKERS_PER_CORE = 4
#: Largest first message a Dask scheduler's greeting is taken to have (a few hundred
#: bytes in practice).
_GREETING_MOST = 1 << 20


def _probe(address: str, deadline: float) -> None:
    """Check that a Dask scheduler answers at ``address`` before ``distributed.Client`` is
    pointed at it: Dask's handshake waits without a time limit for the first message, and
    reads its length from the first 8 bytes (a listener that never answers would hang the
    sweep; an HTTP server's reply would be read as a message of exabytes). A Dask server
    greets first: an 8-byte length, then that many bytes; both must come before
    ``deadline`` and the length must be plausible."""
    import socket
    import struct

    from distributed.comm.addressing import parse_address, parse_host_port

    host, port = parse_host_port(parse_address(address)[1])

    def left() -> float:
        t = deadline - time.monotonic()
        if t <= 0:
            raise TimeoutError("no answer")
        return t

    def recv(sock, n: int) -> bytes:
        data = b""
        while len(data) < n:
            sock.settimeout(left())
            part = sock.recv(n - len(data))
            if not part:
                raise ConnectionError("the connection was closed")
            data += part
        return data

    try:
        with socket.create_connection((host, port), timeout=left()) as sock:
            (n,) = struct.unpack("<Q", recv(sock, 8))
            if not 0 < n <= _GREETING_MOST:
                raise _NotDask(f"its first bytes are {struct.pack('<Q', n)!r}")
            recv(sock, n)
    except _NotDask as exc:
        raise InputError(f"{address!r} is not a Dask scheduler ({exc}); give the address "
                         f"of a running dask scheduler, tcp://HOST:PORT") from None
    except TimeoutError:
        raise InputError(f"no Dask scheduler answered at {address!r} within "
                         f"{CONNECT_TIMEOUT:g} s; give the address of a running dask "
                         f"scheduler, tcp://HOST:PORT") from None
    except OSError as exc:
        why = " ".join(str(exc).split())[:200] or type(exc).__name__
        raise InputError(f"cannot reach the Dask scheduler at {address!r} within "
                         f"{CONNECT_TIMEOUT:g} s ({why})") from None


class _NotDask(Exception):
    pass


def _connect_scheduler(distributed, address: str):
    """A client of the scheduler at ``address`` (checked by :func:`_probe`, then connected
    within :data:`CONNECT_TIMEOUT`), with at least one worker within another
    :data:`CONNECT_TIMEOUT`."""
    deadline = time.monotonic() + CONNECT_TIMEOUT
    _probe(address, deadline)
    try:
        c = distributed.Client(address, timeout=max(1.0, deadline - time.monotonic()))
    except (OSError, TimeoutError, ValueError) as exc:
        raise InputError(f"cannot reach the Dask scheduler at {address!r} within "
                         f"{CONNECT_TIMEOUT:g} s ({' '.join(str(exc).split())[:200]})"
                         ) from None
    try:
        c.wait_for_workers(1, timeout=CONNECT_TIMEOUT)
    except (TimeoutError, OSError):
        c.close()
        raise SnakecgError(f"the Dask scheduler at {address!r} has no workers (none joined "
                           f"within {CONNECT_TIMEOUT:g} s); start some with dask worker "
                           f"{address}") from None
    except BaseException:
        c.close()
        raise
    return c


def connect(*, client=None, scheduler=None, workers=None):
    """``(client, close)``: the given client, one connected to ``scheduler``, or a new local
    cluster of ``workers`` single-threaded worker processes on the loopback interface,
    reachable only with its own temporary TLS credentials (:func:`_local_cluster`);
    ``close()`` shuts down whatever this call started."""
    distributed = _distributed()
    if client is not None:
        if not isinstance(client, distributed.Client):
            raise InputError(f"client must be a dask.distributed.Client, got "
                             f"{type(client).__name__}")
        return client, lambda: None
    if scheduler is not None:
        c = _connect_scheduler(distributed, check_scheduler(scheduler))
        return c, c.close
    n = check_workers(workers)
    import dask

    # Dask's nannies start workers with MALLOC_TRIM_THRESHOLD_=65536 (and leave it in this
    # process's environment, so every later spawn inherits it); with it, glibc returns the
    # extremes' NumPy temporaries to the system at once and maps them anew: 1.6x the CPU
    # time per configuration, measured. Workers started here keep glibc's default.
    if os.environ.get("MALLOC_TRIM_THRESHOLD_") == str(
            dask.config.get("distributed.nanny.pre-spawn-environ.MALLOC_TRIM_THRESHOLD_",
                            None)):
        del os.environ["MALLOC_TRIM_THRESHOLD_"]
    try:
        with dask.config.set({"distributed.nanny.pre-spawn-environ.MALLOC_TRIM_THRESHOLD_":
                              None}):
            cluster = _local_cluster(distributed, n)
    except InputError:
        raise
    except Exception as exc:  # noqa: BLE001 - reported as a failure, exit 1
        raise SnakecgError(f"could not start a local Dask cluster of {n} workers: "
                           f"{type(exc).__name__}: {' '.join(str(exc).split())[:300]}"
                           ) from None
    c = distributed.Client(cluster, security=cluster.security)

    def close():
        c.close()
        cluster.close()

    return c, close


def is_local(client) -> bool:
    """Whether ``client``'s workers are processes (or threads) of this machine: its cluster is
    a ``distributed.LocalCluster`` (as the ones :func:`connect` starts). A client connected
    to a scheduler's address does not know its cluster, and counts as not local."""
    from distributed import LocalCluster

    return isinstance(getattr(client, "cluster", None), LocalCluster)


def concurrency(client) -> int:
    """Tasks ``client``'s cluster runs at once (its workers' threads), at least 1."""
    try:
        return max(1, sum(client.nthreads().values()))
    except Exception:  # noqa: BLE001 - a cluster that does not say: one at a time
        return 1


def fills_machine(client) -> bool:
    """Whether ``client``'s workers have at least one thread per core of this machine (then
    this process has no core of its own to write the store on)."""
    return concurrency(client) >= (os.cpu_count() or 1)


#: Dask settings of the local clusters started here: no statistical profiler in the workers
#: (it samples the computing thread every 10 ms and takes the GIL from it), and the system and
#: memory monitors, the event loops' tick (a check for blocked loops, every 20 ms by default)
#: and work stealing at a slower pace. With Dask's defaults an idle 2-worker cluster kept about
#: 0.18 of a core busy (scheduler and client 0.07, each worker 0.05), with these 0.02,
#: measured: time the workers' computation lacks on a machine with as many cores as workers.
LOCAL_CONFIG = {"distributed.worker.profile.enabled": False,
                "distributed.admin.system-monitor.interval": "5s",
                "distributed.worker.memory.monitor-interval": "1s",
                "distributed.admin.tick.interval": "1s",
                "distributed.scheduler.work-stealing-interval": "1s"}


def _security():
    """Temporary TLS credentials for one local cluster (``Security.temporary()``: a key and
    a self-signed certificate made in memory, handed to the worker processes through their
    start-up pipe; Dask writes them for an instant into a private temporary folder, mode
    0700, while a TLS context loads them): the scheduler, nannies and workers accept only
    peers that present them, so no other program, and no other user of the machine, can
    connect to the cluster and run code in it."""
    try:
        from distributed.security import Security

        return Security.temporary()
    except ImportError:
        raise InputError("sweeps need the sweep extra (Dask, Zarr, xxhash, xarray and "
                         "cryptography, for the local cluster's TLS): pip install "
                         "'snakecg[sweep]'") from None


def _local_cluster(distributed, n: int, security=True):
    """A local cluster of ``n`` single-threaded worker processes on 127.0.0.1, every
    listener TLS with temporary credentials (:func:`_security`; ``security=None`` is for the
    benchmark's comparison only)."""
    import dask

    env = {"DASK_" + key.upper().replace(".", "__").replace("-", "_"): str(value)
           for key, value in LOCAL_CONFIG.items()}  # read by each worker process at start
    sec = _security() if security is True else security
    with dask.config.set(LOCAL_CONFIG):  # the scheduler's, in this process
        return distributed.LocalCluster(
            n_workers=n, threads_per_worker=1, processes=True, host="127.0.0.1",
            security=sec, protocol="tls://" if sec is not None else "tcp://",
            # CRITICAL: a worker whose heartbeat meets the scheduler closing at the end of a
            # sweep logs that race as an error with a traceback; a chunk's own failure
            # reaches the sweep through its future and is reported there
            dashboard_address="127.0.0.1:0", silence_logs=logging.CRITICAL,
            # one C thread per worker process: the processes are the parallelism
            env={"SNAKECG_THREADS": os.environ.get("SNAKECG_THREADS", "1"), **env},
        )


def _has_bokeh() -> bool:
    import importlib.util

    return importlib.util.find_spec("bokeh") is not None


def dashboard_of(client) -> str | None:
    """The dashboard's address, when the scheduler serves one (it needs bokeh on the
    scheduler's machine; without it Dask only reserves the port)."""
    try:
        if "dashboard" not in client.scheduler_info().get("services", {}):
            return None
        if not client.run_on_scheduler(_has_bokeh):
            return None
        return client.dashboard_link
    except Exception:  # noqa: BLE001 - no dashboard is not an error
        return None


def progress_mode(progress, stream=None) -> str:
    """``"bar"``, ``"lines"`` or ``"off"`` for the ``progress`` argument of a sweep."""
    stream = sys.stderr if stream is None else stream
    if progress in ("bar", "lines", "off"):
        return progress
    if progress is False:
        return "off"
    if progress is not None and progress is not True:
        raise InputError(f"progress must be None (automatic), True, False, 'bar', 'lines' or "
                         f"'off', got {progress!r}")
    if progress is None and os.environ.get("SNAKECG_PROGRESS", "").strip() == "0":
        return "off"
    return "bar" if _isatty(stream) else "lines"


def _isatty(stream) -> bool:
    try:
        return bool(stream.isatty())
    except (AttributeError, ValueError):
        return False


def start_bar(client, futures):
    """Dask's text progress bar over ``futures``, drawn on standard error (standard output
    stays for results), running on the client's event loop."""
    from distributed.diagnostics.progressbar import TextProgressBar

    class _Bar(TextProgressBar):
        def _draw_bar(self, remaining, all, **kwargs):
            frac = (1 - remaining / all) if all else 1.0
            sys.stderr.write("\r[{0:<{1}}] | {2}% Completed | {3}".format(
                "#" * int(self.width * frac), self.width, int(100 * frac),
                _format_time(self.elapsed)))
            sys.stderr.flush()

        def _draw_stop(self, **kwargs):
            sys.stderr.write("\33[2K\r")
            sys.stderr.flush()

    bar = _Bar(futures, scheduler=client.scheduler.address, start=False)
    client.loop.add_callback(bar.listen)
    return bar


def end_bar(bar, wait: float = 1.0) -> None:
    """After the last chunk: let the bar draw its end, or draw it here. A sweep of a few fast
    chunks can finish (and release its futures) before the bar's first report from the
    scheduler; the bar then never hears of them, and would show nothing."""
    deadline = time.monotonic() + wait
    while getattr(bar, "status", None) not in ("finished", "error"):
        if time.monotonic() >= deadline:
            bar._draw_bar(remaining=0, all=len(bar.keys))
            bar._draw_stop()
            comm = getattr(bar, "comm", None)
            if comm is not None:
                comm.abort()
            return
        time.sleep(0.02)


def _format_time(t: float) -> str:
    from distributed.diagnostics.progress import format_time

    return format_time(t)


class ProgressLines:
    """One line on standard error each time another tenth of the chunks is written."""

    def __init__(self, total_chunks: int, already: int, configurations: int, stream=None):
        self.total, self.done = total_chunks, already
        self.configurations = configurations
        self.stream = sys.stderr if stream is None else stream
        self.t0 = time.perf_counter()
        self.start_done = already
        self.next_tenth = self.done * 10 // max(self.total, 1) + 1

    def due(self) -> bool:
        """Whether the next chunk's :meth:`update` prints a line (the caller records the
        chunks first, so that a line counts only chunks recorded in the store)."""
        return (self.done + 1) * 10 // max(self.total, 1) >= self.next_tenth

    def update(self, configurations_done: int) -> None:
        self.done += 1
        tenth = self.done * 10 // max(self.total, 1)
        if tenth >= self.next_tenth:
            self.next_tenth = tenth + 1
            dt = time.perf_counter() - self.t0
            rate = (self.done - self.start_done) / dt if dt > 0 else 0.0
            left = (self.total - self.done) / rate if rate > 0 else 0.0
            self.stream.write(
                f"snakecg sweep: {100 * self.done // self.total:3d}% ({self.done}/{self.total} "
                f"chunks, {configurations_done:,} of {self.configurations:,} configurations) "
                f"after {dt:.1f} s, about {left:.0f} s left\n")
            self.stream.flush()
