"""Running tasks (operating points, continuation sweeps) in parallel: a pool of local processes by
default (forked on Linux, so they start in milliseconds with this process's imports) or the
workers of any dask.distributed scheduler (`scheduler` = its address), one FMU instance per worker
process reused through fmi2Reset, a tqdm progress bar with ETA, and a callback per result so the
caller can write it at once. `workers=0` runs everything in this process (tests, debugging).

The FMU travels to the workers as bytes (with every task locally, scattered once to a dask
cluster), so remote workers need only the `hypoid` package and its pinned dependencies
installed, not the repository."""

import atexit
import concurrent.futures
import contextlib
import hashlib
import os
import pathlib
import signal
import sys
import threading
import time
import traceback

from tqdm import tqdm

_INSTANCES = {}  # (fmu sha, thread) -> Instance, per worker process
_LOCK = threading.Lock()
_FMUS = {}  # sha -> bytes of the FMUs this process has read: forked workers have them too


class FmuRef:
    """The FMU's content hash and bytes (the bytes may be a dask future after scatter)."""

    def __init__(self, path):
        self.path = str(path)
        self.data = pathlib.Path(path).read_bytes()
        self.sha = hashlib.sha256(self.data).hexdigest()
        _FMUS[self.sha] = self.data


class PointTimeout(RuntimeError):
    """A task used more CPU time than it may (hypoid.study.steady.Settings.max_cpu for a point);
    it comes back as {'status': 'timeout', ...}."""


# ---------------------------------------------------------------------------- worker side
def instance_for(sha, data):
    """This process's (and thread's) FMU instance, created on first use."""
    from hypoid.fmu.instance import Instance, unzip_bytes

    key = (sha, threading.get_ident())
    with _LOCK:
        inst = _INSTANCES.get(key)
    if inst is None:
        data = _FMUS[sha] if data is None else data  # None: this process was forked with it
        inst = Instance(unzip_bytes(sha, data), name=f"worker-{os.getpid()}")
        with _LOCK:
            _INSTANCES[key] = inst
    return inst


def drop_instance(sha):
    """Frees this thread's instance (after an error its state is not trusted)."""
    with _LOCK:
        inst = _INSTANCES.pop((sha, threading.get_ident()), None)
    if inst is not None:
        with contextlib.suppress(Exception):
            inst.close()


@atexit.register
def _close_all():
    for key in list(_INSTANCES):
        with contextlib.suppress(Exception):
            _INSTANCES.pop(key).close()


def guarded(sha, data, fn, *args):
    """Runs fn(instance, *args); failures come back as {'status': 'error', ...}."""
    from hypoid.fmu.instance import FmuError

    t0 = time.process_time()
    try:
        return fn(instance_for(sha, data), *args)
    except PointTimeout as e:
        drop_instance(sha)
        return {"status": "timeout", "message": str(e), "cpu_s": time.process_time() - t0}
    except FmuError as e:
        drop_instance(sha)
        return {"status": "error", "message": str(e), "cpu_s": time.process_time() - t0}
    except Exception as e:  # noqa: BLE001 - report, do not kill the whole study
        drop_instance(sha)
        return {"status": "error", "message": f"{type(e).__name__}: {e}",
                "traceback": traceback.format_exc(limit=5), "cpu_s": time.process_time() - t0}


def each(inst, sha, items):
    """A task of tasks: items [(fn, args)] in turn on this worker, each as guarded runs it (a
    failure ends only its own item; the next gets a new instance, made from the FMU's bytes the
    process was forked with): {'status': 'ok', 'results': [...]}. `inst` is the instance the
    first item runs on."""
    return {"status": "ok", "results": [guarded(sha, None, fn, *args) for fn, args in items]}


# ---------------------------------------------------------------------------- client side
def _forget_parent_instances():
    """A forked worker starts without the instances of the process it was forked from, and leaves
    SIGINT to its parent (a Ctrl-C reaches the whole process group): the parent ends it."""
    _INSTANCES.clear()
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)


class Terminated(KeyboardInterrupt):
    """SIGTERM, raised in the main thread like a Ctrl-C so that the same clean-up runs."""


@contextlib.contextmanager
def sigterm_as_interrupt():
    """SIGTERM raises Terminated in the main thread while the block runs (elsewhere: as is)."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return

    def handler(signum, frame):
        raise Terminated("SIGTERM")

    before = signal.signal(signal.SIGTERM, handler)
    try:
        yield
    finally:
        signal.signal(signal.SIGTERM, before)


class LocalPool:
    """`workers` processes on this machine, one task at a time each. A dask LocalCluster took
    2-3 s to start and 0.7 s to close on this machine's 2 cores, a tenth of the default study."""

    def __init__(self, workers):
        import multiprocessing

        method = "fork" if sys.platform.startswith("linux") else "spawn"
        self.pool = concurrent.futures.ProcessPoolExecutor(
            workers, mp_context=multiprocessing.get_context(method),
            initializer=_forget_parent_instances)
        # the FMUs read before the workers are forked (they start on the first submit) travel
        # with them; the bytes of others, with each task (2 MB each: 0.6 s of CPU in pickles
        # and pipes over the default study's 274 tasks)
        self.inherited = set(_FMUS) if method == "fork" else set()

    def run(self, tasks, fmu, on_result, bar):
        data = None if fmu.sha in self.inherited else fmu.data
        futures = {self.pool.submit(guarded, fmu.sha, data, fn, *args): key
                   for key, fn, args in tasks}  # in list order: the long sweeps first
        try:
            for f in concurrent.futures.as_completed(futures):
                on_result(futures[f], f.result())
                bar.update()
        except BaseException:
            for f in futures:
                f.cancel()
            raise

    def close(self):
        self.pool.shutdown(wait=True, cancel_futures=True)

    def abort(self):
        """Ends the workers now, also those in the middle of a task (a point may take minutes)."""
        processes = list((self.pool._processes or {}).values())
        self.pool.shutdown(wait=False, cancel_futures=True)
        for p in processes:
            with contextlib.suppress(Exception):
                p.terminate()
        for p in processes:
            with contextlib.suppress(Exception):
                p.join(5.0)


def inherits(client, fmu):
    """Whether client's workers hold fmu's bytes from their fork (a LocalPool forked after the
    FMU was read), so that they can make a new instance without being sent them (each)."""
    return isinstance(client, LocalPool) and fmu.sha in client.inherited


def call_all(calls, workers=2):
    """[fn()] of argument-free picklable callables, on `workers` local processes (0: here)."""
    if workers == 0:
        return [fn() for fn in calls]
    with sigterm_as_interrupt():
        pool = LocalPool(workers)
        try:
            out = list(pool.pool.map(_call, calls))
        except BaseException:
            pool.abort()
            raise
        pool.close()
        return out


def _call(fn):
    return fn()


@contextlib.contextmanager
def executor(scheduler=None, workers=2):
    """A LocalPool of `workers` processes, a dask Client of `scheduler`, or None for in-process
    runs (workers = 0)."""
    if scheduler is None and workers == 0:
        yield None
        return
    if scheduler is None:
        with sigterm_as_interrupt():
            pool = LocalPool(workers)
            try:
                yield pool
            except BaseException:
                pool.abort()  # an interrupt, SIGTERM or error: no worker outlives the run
                raise
            pool.close()
        return
    from dask.distributed import Client

    client = Client(scheduler)
    try:
        yield client
    finally:
        client.close()


def run(tasks, fmu, on_result, client=None, desc="points"):
    """tasks: [(key, fn, args)]; fn(instance, *args) runs on a worker; on_result(key, result)
    runs here as each finishes. Returns the number of tasks run."""
    if not tasks:
        return 0
    bar = tqdm(total=len(tasks), desc=desc, unit="task", smoothing=0.1, dynamic_ncols=True)
    try:
        if client is None:
            for key, fn, args in tasks:
                on_result(key, guarded(fmu.sha, fmu.data, fn, *args))
                bar.update()
            return len(tasks)
        if isinstance(client, LocalPool):
            client.run(tasks, fmu, on_result, bar)
            return len(tasks)
        from dask.distributed import as_completed

        data = client.scatter(fmu.data, broadcast=True, hash=True)
        futures = {}
        for key, fn, args in tasks:
            f = client.submit(guarded, fmu.sha, data, fn, *args, pure=False)
            futures[f] = key
        try:
            for f in as_completed(futures):
                on_result(futures[f], f.result())
                bar.update()
        except BaseException:
            client.cancel(list(futures))
            raise
        return len(tasks)
    finally:
        bar.close()
