"""One sweep at a time per store: the lock a sweep holds on its store (:func:`store_lock`)."""

from __future__ import annotations

import os
import sys
from pathlib import Path

from ..errors import InputError

__all__ = ["store_lock", "StoreLock"]


def store_lock(store: Path, *, quiet: bool = False) -> StoreLock:
    """The lock of the store at ``store`` (the file ``.NAME.lock`` beside it while a sweep
    runs), taken: held for the whole sweep, a second sweep into the same store waits, saying
    so on standard error unless ``quiet``, until the first ends (then it resumes the store:
    it finds the chunks complete, or is refused if made with other arguments), instead of
    both creating or writing it at once. Use it as a context manager."""
    lock = StoreLock(store)
    if not lock.acquire(block=False):
        if not quiet:
            sys.stderr.write(f"snakecg sweep: {store} is in use by another sweep; waiting for "
                             f"it to finish\n")
            sys.stderr.flush()
        lock.acquire(block=True)
    return lock


class StoreLock:
    """An exclusive ``flock`` on the lock file of a store, removed when released, so that no
    lock file is left beside the store: whoever takes the lock checks that the file it
    locked is still the one at the path (else the previous holder removed it, and it tries
    again), the usual way to remove a lock file safely. Without ``fcntl`` (Windows),
    ``filelock``'s lock, whose file stays."""

    def __init__(self, store: Path):
        self.store = Path(store)
        self.path = self.store.with_name(f".{self.store.name}.lock")
        self.fd, self.fallback = None, None

    def acquire(self, block: bool) -> bool:
        """Take the lock (waiting for it with ``block``); whether it was taken."""
        try:
            import fcntl
        except ImportError:  # pragma: no cover - not POSIX
            from filelock import FileLock, Timeout

            self.fallback = self.fallback or FileLock(str(self.path))
            try:
                self.fallback.acquire(timeout=-1 if block else 0)
                return True
            except Timeout:
                return False
        while True:
            try:
                fd = os.open(self.path, os.O_RDWR | os.O_CREAT, 0o600)
            except OSError as exc:
                raise InputError(f"--out {str(self.store)!r}: cannot create its lock file "
                                 f"beside it ({' '.join(str(exc).split())}); the folder "
                                 f"must be writable") from None
            try:
                fcntl.flock(fd, fcntl.LOCK_EX | (0 if block else fcntl.LOCK_NB))
            except BlockingIOError:
                os.close(fd)
                return False
            except BaseException:
                os.close(fd)
                raise
            try:
                same = os.fstat(fd).st_ino == os.stat(self.path).st_ino
            except FileNotFoundError:
                same = False
            if same:
                self.fd = fd
                return True
            os.close(fd)  # removed meanwhile by the previous holder: take the new one

    def release(self) -> None:
        """Remove the lock file and let the lock go (in that order: a sweep waiting on this
        file then finds it removed and takes a new one)."""
        if self.fallback is not None:  # pragma: no cover - not POSIX
            self.fallback.release()
            return
        try:
            os.unlink(self.path)
        except OSError:
            pass
        os.close(self.fd)
        self.fd = None

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.release()
