"""The student's package runs in a separate process; the grader (pytest, which computes and writes the grade) never
imports it.

:class:`Sandbox` starts that process on first use and reuses it for every call of the grading session:

* **What it sees.** A private folder (``gandalf-sandbox-*`` in the system's temp folder, mode 0700) holds a copy of
  the student's package as ``<step>/exercises``, the step packages' other modules (links, never ``solutions/``),
  the engine, the server (``sandbox_child.py``) and its own temp folder and bytecode cache. Python runs isolated
  (``-I``) with that folder first on ``sys.path`` and as its working folder, then the grader's package folders (its
  site-packages, and a ``pip install --target`` folder on its path, which ``-I`` would drop); the checkout is not
  on ``sys.path``.
* **Who it is.** When the grader runs as root (Gradescope does), the process runs as a user of its own (a uid without
  a name, one per sandbox), in its own pid namespace and a mount namespace where every top folder but the system's
  (``/usr``, ``/etc``, ...), so ``/tmp``, ``/home``, ``/root``, ``/opt`` and any other where a copy of the course may
  lie, is covered by an empty read-only folder and only what it needs is put back read-only (the engine, the step
  packages with ``solutions/`` covered again, the virtual environment, Python): no solution, test, git history, output
  folder or other submission is there to read. As any other user, when the system allows it, the same covers are made
  in a user namespace (the same uid, mapped to its root), with Python read-only too, the graders' bytecode cache and
  the folders of ``GANDALF_SANDBOX_HIDE`` covered, its own pid namespace, and every capability dropped before the
  student's code runs (so that it cannot undo a mount); as root where no namespace may be made (a container without
  ``CAP_SYS_ADMIN``), a user of its own still, with the folders the grader knows to be secret closed to other users
  (``chmod o-rwx``); where the system allows neither, the student's process can read and write what its user
  can (``isolation()`` says which applies; the grade records it;
  ``GANDALF_SANDBOX_ISOLATION`` asks for a weaker one, to check it).
* **Limits.** Memory (RLIMIT_AS), processes (RLIMIT_NPROC, for its own user), file size (RLIMIT_FSIZE), CPU time
  (RLIMIT_CPU), and a wall-clock budget per call kept by this process: a call past it ends the sandboxed process
  (and every process of its user), the function is remembered as hung so that its later calls fail at once, and
  the next call of another function starts a fresh process.
"""

from __future__ import annotations

import builtins
import functools
import importlib
import marshal
import os
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import types
from collections.abc import Callable
from pathlib import Path
from typing import Any

from . import pycache_dir, wire

ROOT = Path(__file__).resolve().parents[2]
HIDE_ENV = "GANDALF_SANDBOX_HIDE"
MEMORY_LIMIT = 3 * 2**30
FILE_LIMIT = 64 * 2**20
PROCESS_LIMIT = 64
CPU_LIMIT = 600
#: Seconds the sandboxed process may take to start and import the student's package.
STARTUP_BUDGET = 30.0

_BOOT = """\
import os, resource, sys
private, pkgs = sys.argv[1], sys.argv[2]
for limit, value in ((resource.RLIMIT_AS, {memory}), (resource.RLIMIT_FSIZE, {fsize}), (resource.RLIMIT_CPU, {cpu}),
                     (resource.RLIMIT_CORE, 0), (resource.RLIMIT_NPROC, {nproc})):
    if value is not None:
        resource.setrlimit(limit, (value, value))
sys.meta_path[:] = [f for f in sys.meta_path if "editable" not in type(f).__name__.lower()
                    and "editable" not in getattr(f, "__name__", "").lower()]
sys.path[:] = [pkgs, private] + [p for p in sys.path if p and "site-packages" not in p or p.endswith("site-packages")]
sys.path += [p for p in {site} if p not in sys.path]  # the grader's packages from its path (pip --target)
sys.pycache_prefix = os.path.join(private, "pycache")
sys.argv = sys.argv[2:]
import gandalf_child
gandalf_child.main()
"""


class SandboxFailure(Exception):
    """A call of the student's code that did not come back: it hung past its budget or ended the process."""


@functools.cache
def _namespaces_work(*flags: str) -> bool:
    try:
        return subprocess.run(["unshare", *flags, "true"], capture_output=True, timeout=10).returncode == 0
    except (OSError, subprocess.SubprocessError):
        return False


#: Environment variable that asks for a weaker isolation than the machine allows ("mount", "user" or "process"): to
#: check what the grader does where a stronger one is not available (the attack replay and CI do).
ISOLATION_ENV = "GANDALF_SANDBOX_ISOLATION"
MODES = ("user+mount", "mount", "user", "process")

#: The system's top folders, left as they are in the student's mount namespace (every other is covered).
SYSTEM_FOLDERS = frozenset({"usr", "lib", "lib32", "lib64", "libx32", "bin", "sbin", "etc", "proc", "dev", "sys", "run",
                            "var", "boot"})


def isolation() -> str:
    """How the student's process is kept from the checkout here: "user+mount" (its own uid, the solutions and
    tests covered), "mount" (the same user in a user + mount + pid namespace without capabilities: the solutions,
    tests and bytecode cache covered, the checkout and Python read-only), "user" (root where no namespace may be made,
    as in a container without ``CAP_SYS_ADMIN``: a user of its own, the folders the grader knows to be secret closed
    to other users), or "process" (a separate process only: it could read and write the files its user can).
    ``$GANDALF_SANDBOX_ISOLATION`` may ask for a weaker one."""
    wanted = os.environ.get(ISOLATION_ENV, "").strip()
    if wanted and wanted not in MODES:
        raise ValueError(f"${ISOLATION_ENV}={wanted!r}: expected one of {MODES}")
    floor = MODES.index(wanted) if wanted else 0
    if (floor == 0 and hasattr(os, "geteuid") and os.geteuid() == 0 and shutil.which("setpriv")
            and _namespaces_work("--mount")):
        return "user+mount"
    if floor <= 1 and shutil.which("setpriv") and _namespaces_work("--user", "--map-root-user", "--mount", "--pid",
                                                                   "--fork", "--mount-proc"):
        return "mount"
    if floor <= 2 and hasattr(os, "geteuid") and os.geteuid() == 0 and shutil.which("setpriv"):
        return "user"
    return "process"


#: What each isolation means for the grade, in one sentence (the doctor, the grade files and the console say it).
MEANING = {
    "user+mount": "the student's code runs as a user of its own in a mount and pid namespace: it cannot read the "
                  "solutions, the tests or other submissions, nor write the grade",
    "mount": "the student's code runs in a user, mount and pid namespace without capabilities: it cannot read the "
             "solutions, the tests or other submissions, nor write the grade",
    "user": "the student's code runs as a user of its own (no namespace could be made here): the solutions, hidden "
            "tests, mutants, output folders and other submissions the grader knows, and the solutions of copies of "
            "the course beside the checkout, are closed to other users (chmod o-rwx), and it can write no file of the "
            "grader's; a copy of the course elsewhere on this machine that every user may read, it could read too",
    "process": "NOT ISOLATED: the student's code runs in a separate process as the grader's own user, without "
               "namespaces, and could read the solutions and tests and write any file that user can, the grade "
               "included; a grade made so can be forged: grade as root (Gradescope's autograder, a container) or "
               "where unprivileged user namespaces are allowed",
}


def isolation_warning(mode: str) -> str | None:
    """The warning a grade made under ``mode`` carries, with why (None where the student's code was kept from the
    checkout)."""
    if mode != "process":
        return None
    why = (f"${ISOLATION_ENV}=process asked for it" if os.environ.get(ISOLATION_ENV, "").strip() == "process" else
           "'unshare --user --map-root-user --mount --pid' and setpriv are refused or missing here")
    return f"WARNING: {MEANING['process']} ({why})"


def _editable_roots() -> set[Path]:
    """Checkouts an editable install of the project points at (its finder's mapping)."""
    roots: set[Path] = set()
    for entry in sys.path:
        for finder in Path(entry).glob("__editable__*finder.py") if entry and Path(entry).is_dir() else ():
            text = finder.read_text(errors="replace")
            for line in text.splitlines():
                if line.startswith("MAPPING"):
                    roots |= {Path(p).parent for p in line.split("'")[3::4]}
    return roots


def site_folders() -> list[Path]:
    """The folders this Python imports installed packages from: its site folders and folders of installed
    distributions on its path (``pip install --target``, a borrowed environment's), never the checkout itself."""
    found = []
    for entry in sys.path:
        path = Path(entry).resolve() if entry else None
        if path and path.is_dir() and path != ROOT.resolve() and (
                entry.endswith("-packages") or any(path.glob("*.dist-info"))):
            found.append(path)
    return list(dict.fromkeys(found))


def hidden_paths(extra: list[str] | tuple[str, ...] = ()) -> list[Path]:
    """The folders the student's process must not see: solutions, tests and git data of every checkout the
    grader knows, plus ``extra`` and ``$GANDALF_SANDBOX_HIDE`` (output folders, other submissions)."""
    paths: set[Path] = set()
    for root in {ROOT, *_editable_roots(), *site_folders()}:  # an installed wheel holds solutions/ too
        paths |= set(root.glob("step*/solutions")) | {root / "tests"}
        git = root / ".git"
        if git.is_file() and git.read_text().startswith("gitdir:"):
            git = Path(git.read_text().split(":", 1)[1].strip()).parents[1]
        paths.add(git)
    cache = pycache_dir()  # the graders' shared bytecode (the student's process has its own)
    for entry in [*extra, *os.environ.get(HIDE_ENV, "").split(os.pathsep), *([cache] if cache else [])]:
        if entry.strip():
            paths.add(Path(entry.strip()))
    return sorted(p.resolve() for p in paths if p.is_dir())


def _secret_parts(hide: list[Path]) -> list[Path]:
    """What of ``hide`` may be closed to other users: a checkout's ``tests`` folder stays open (the shader process,
    a user of its own under ``user+mount``, reads its helpers; the public tests are the student's anyway) except its
    hidden tests (the release's rule, :func:`gandalf_tools.release.is_hidden`) and the mutants; every other folder
    whole."""
    from gandalf_tools.release import is_hidden

    parts = []
    for path in hide:
        if path.name == "tests" and (path.parent / "gandalf_core").is_dir():
            parts += [q for q in path.rglob("*") if is_hidden(q.name)]
            parts += [q for q in (path / "mutants",) if q.is_dir()]
        else:
            parts.append(path)
    return parts


def close_to_others(paths: list[Path]) -> None:
    """Take every permission of other users from ``paths`` (``chmod o-rwx``: the user that owns a folder and its group
    keep theirs): where no mount namespace can cover them, a student's process running as a user of its own can
    then neither list nor read them. They stay so (each grading closes them again)."""
    for path in paths:
        try:
            mode = path.stat().st_mode
            if mode & 0o007:
                path.chmod(mode & ~0o007 & 0o7777)
        except OSError as exc:
            raise PermissionError(f"cannot close {path} to other users for the sandbox: {exc}") from exc


def _step_dirs(graded: list[Path]) -> list[Path]:
    """The checkout's step packages and the graded ones (which may live elsewhere)."""
    return sorted({p.parent.resolve() for p in ROOT.glob("step*/__init__.py")} | set(graded))


#: Modules whose types and functions the two sides may name: the engine's and the steps' own, never a student's
#: package or a reference solution.
ALLOWED_MODULE = re.compile(r"^(gandalf_core(\..*)?|step\d\d_[a-z_]+(\.(?!exercises|solutions)[a-z_]+)*)$")


#: Modules a shipped function may use by name (see :func:`recipe`).
SHIPPED_MODULES = ("numpy", "math")


def _names_of(code: types.CodeType) -> set[str]:
    names = set(code.co_names)
    for const in code.co_consts:
        if isinstance(const, types.CodeType):
            names |= _names_of(const)
    return names


def recipe(fn: Callable[..., Any]) -> dict[str, Any] | None:
    """How the sandbox can run ``fn`` itself instead of calling it back: for a function of the engine or a step
    (never a student's package nor a solution) whose captured values, defaults and global names are plain data or
    ``numpy``/``math``, its code (``marshal``: course code going to the sandbox, never read back) and those values.
    An acceleration function that a simulation calls thousands of times then costs no round trip each. None for
    any other function (it is called back)."""
    if not isinstance(fn, types.FunctionType) or not ALLOWED_MODULE.match(fn.__module__ or "") or fn.__kwdefaults__:
        return None
    names: dict[str, Any] = {}
    for name in _names_of(fn.__code__):
        if name in fn.__globals__:
            value = fn.__globals__[name]
            names[name] = {"module": value.__name__} if isinstance(value, types.ModuleType) else value
            if isinstance(value, types.ModuleType) and value.__name__ not in SHIPPED_MODULES:
                return None
        elif not hasattr(builtins, name):
            return None
    data = {"code": marshal.dumps(fn.__code__), "name": fn.__name__, "globals": names,
            "cells": [c.cell_contents for c in fn.__closure__ or ()], "defaults": fn.__defaults__}
    try:
        wire.encode_value(data, [])
    except (wire.WireError, ValueError):  # a captured object or function: call it back instead
        return None
    return data


_made = iter(range(1 << 30))
_recipe_numbers = iter(range(1 << 62))  # numbers of the recipes sent (see Sandbox._exchange)


def _uid() -> int:
    """A user id of the sandbox's own (no name needed): one per sandbox of this process (a step's), so that ending
    the processes of one never touches another's."""
    return 200000 + (os.getpid() * 16 + next(_made) % 16) % 1600000


class Sandbox:
    """One sandboxed process for the graded packages of a grading session, one per step (started on first use,
    again after a hang or a crash)."""

    def __init__(self, step: str, folder: Path, *, hide: tuple[str, ...] = (), memory: int = MEMORY_LIMIT,
                 shown: tuple[Path, ...] = (), shader_cache: Path | None = None,
                 env: dict[str, str] | None = None) -> None:
        self.hide, self.memory = tuple(hide), memory
        self.env = dict(env or {})  # set in the process's environment besides the few it always gets
        # A folder of the grader's where the GPU driver keeps compiled shaders across this kind of process (writable
        # there); else the process's own folder (Mesa keeps none where it finds no home of the user: every context
        # compiled every program again).
        self.shader_cache = Path(shader_cache).resolve() if shader_cache is not None else None
        # Course folders put back read-only for a process that runs no student Python (the shader process: the test
        # helpers that render with the student's shaders); never a step's solutions.
        self.shown = tuple(Path(p).resolve() for p in shown)
        self.folders: dict[str, Path] = {}  # step package -> the folder graded as its exercises
        self.step_dirs: dict[str, Path] = {}  # step package -> its own folder (course code)
        self.imported: set[str] = set()  # the packages the running process has imported
        self.import_errors: dict[str, str] = {}
        self.add(step, folder)
        self.mode = isolation()
        # "user" mode keeps no mount namespace, so a process shown course folders (the shader process, which runs no
        # student Python) stays the grader's user, to read them; every other process is a user of its own.
        self.uid = _uid() if self.mode == "user+mount" or (self.mode == "user" and not self.shown) else None
        self.generation = 0  # bumped per process started: instances made in an older one are gone
        self.proc: subprocess.Popen[bytes] | None = None
        self.private: Path | None = None
        self._to_child = self._from_child = -1
        self.failed: dict[str, str] = {}  # target -> the sentence its later calls fail with
        self.callables = []
        self._sent: set[int] = set()
        self._recipes: dict[int, tuple[Callable[..., Any], dict[str, Any] | None]] = {}

    def add(self, step: str, folder: Path) -> None:
        """Grade ``folder`` as ``<step>.exercises`` too (a process already running starts again to include it)."""
        if self.folders.get(step) == Path(folder):
            return
        self.folders[step] = Path(folder)
        # The step package itself (course code, already imported by the tests): usually one of the checkout's.
        self.step_dirs[step] = Path(importlib.import_module(step).__file__ or "").resolve().parent
        if getattr(self, "proc", None) is not None:
            self.stop()

    # --- the private folder -------------------------------------------------------------------------
    def _lay_out(self) -> Path:
        private = Path(tempfile.mkdtemp(prefix="gandalf-sandbox-"))
        pkgs = private / "pkgs"
        pkgs.mkdir()
        (pkgs / "gandalf_core").symlink_to(ROOT / "gandalf_core")
        for shown in self.shown:
            if shown.parent == ROOT and (shown / "__init__.py").is_file():  # a package of the course (gandalf_tools)
                (pkgs / shown.name).symlink_to(shown)
        for source in _step_dirs(list(self.step_dirs.values())):
            target = pkgs / source.name
            target.mkdir()
            for entry in source.iterdir():
                if entry.name not in ("solutions", "exercises", "__pycache__"):
                    (target / entry.name).symlink_to(entry)
            if source.name in self.folders:
                shutil.copytree(self.folders[source.name], target / "exercises", symlinks=False,
                                ignore=shutil.ignore_patterns("__pycache__", "*.pyc", "solutions"))
            elif (source / "exercises").is_dir():
                shutil.copytree(source / "exercises", target / "exercises",
                                ignore=shutil.ignore_patterns("__pycache__", "*.pyc"))
        here = Path(__file__).resolve().parent
        shutil.copy(here / "sandbox_child.py", private / "gandalf_child.py")
        shutil.copy(here / "wire.py", private / "gandalf_wire.py")
        for name in ("tmp", "home", "pycache"):
            (private / name).mkdir()
        if self.shader_cache is not None:
            self.shader_cache.mkdir(mode=0o700, parents=True, exist_ok=True)
        if self.uid is not None:
            caches = [self.shader_cache, *self.shader_cache.rglob("*")] if self.shader_cache is not None else []
            for path in [private, *private.rglob("*"), *caches]:
                os.lchown(path, self.uid, self.uid)
        private.chmod(0o700)
        return private

    def _command(self, private: Path, fd_in: int, fd_out: int) -> list[str]:
        boot = _BOOT.format(memory=self.memory, fsize=FILE_LIMIT, cpu=CPU_LIMIT,
                            nproc=PROCESS_LIMIT if self.uid is not None else None,
                            site=[str(p) for p in site_folders()])
        python = [sys.executable, "-I", "-c", boot, str(private), str(private / "pkgs"), str(fd_in), str(fd_out)]
        if self.mode == "process" or (self.mode == "user" and self.uid is None):
            return python
        protected = [private, Path(sys.prefix).resolve(), Path(sys.base_prefix).resolve(), ROOT / "gandalf_core",
                     Path(tempfile.gettempdir()).resolve()]
        solutions = [str(d / "solutions") for d in self.step_dirs.values()]
        hide = [p for p in hidden_paths((*self.hide, *solutions))
                if not any(q == p or p in q.parents for q in protected) and p not in self.shown]
        if self.mode == "user":
            # Without a mount namespace only permissions keep it out: the secret folders above and every copy of the
            # course beside this checkout (clones and worktrees of one folder) are closed to other users.
            beside = [p.resolve() for p in ROOT.parent.glob("*/step[0-9][0-9]_*/solutions") if p.is_dir()]
            close_to_others([*_secret_parts(hide), *beside])
            # No new privileges either: a set-uid program (sudo, su) it finds cannot make it root again.
            return ["setpriv", f"--reuid={self.uid}", f"--regid={self.uid}", "--clear-groups", "--inh-caps=-all",
                    "--bounding-set=-all", "--no-new-privs", "--", *python]
        if self.mode == "user+mount":
            drop = f"exec setpriv --reuid={self.uid} --regid={self.uid} --clear-groups --inh-caps=-all -- \"$@\"\n"
            script, kept = self._only_what_it_needs(private)
            inside = [p for p in hide if any(k in p.parents for k in kept)]  # the rest is covered already
            script += "".join(f"mount -t tmpfs -o ro,size=4k,mode=0555 gandalf-hidden '{p}' || exit 97\n"
                              for p in inside)
            script += drop
            return ["unshare", "--mount", "--propagation", "private", "--pid", "--fork", "--mount-proc", "--",
                    "sh", "-c", script, "sh", *python]
        # The same user (root of a user namespace, mapped to it): the same covers as above (its user may own other
        # copies of the course), Python read-only too (its user may own it), the hidden folders covered; then every
        # capability is dropped, so that it can neither undo a mount nor regain one; its own pid namespace hides the
        # other processes and ends whatever it leaves behind with it.
        script, kept = self._only_what_it_needs(private)
        script += "".join(f"mount --rbind '{p}' '{p}' && mount -o remount,bind,ro '{p}' || exit 97\n"
                          for p in dict.fromkeys([Path(sys.prefix).resolve(), Path(sys.base_prefix).resolve()])
                          if not any(k == p or k in p.parents for k in kept))
        script += "".join(f"[ ! -d '{p}' ] || mount -t tmpfs -o ro,size=4k,mode=0555 gandalf-hidden '{p}' || exit 97\n"
                          for p in hide)
        drop = 'exec setpriv --no-new-privs --bounding-set=-all --inh-caps=-all -- "$@"\n'
        return ["unshare", "--user", "--map-root-user", "--mount", "--propagation", "private", "--pid", "--fork",
                "--mount-proc", "--", "sh", "-c", script + drop, "sh", *python]

    def _only_what_it_needs(self, private: Path) -> tuple[str, list[Path]]:
        """Shell lines (run as root in the new mount namespace) that cover every folder where checkouts, submissions,
        outputs and temp files live (``/tmp``, ``/home``, ``/root``, the checkout's top folder, ...) with an empty
        read-only folder, then put back only what the student's process needs: its private folder, the engine, the
        step packages (their ``solutions/`` covered again below), the virtual environment, the site folders it imports
        packages from (``solutions/`` of an installed course covered too) and Python itself."""
        needed = [ROOT / "gandalf_core", *self.shown, *_step_dirs(list(self.step_dirs.values())),
                  Path(sys.prefix).resolve(), Path(sys.base_prefix).resolve(), Path(sys.executable).resolve().parent,
                  *site_folders()]
        # Every top folder but the system's: another copy of the course may lie anywhere (``/work``, ``/data``,
        # ``/autograder``), not only beside this one.
        tops = {Path("/", p.resolve().parts[1]) for p in [*needed, private, Path(tempfile.gettempdir())]
                if len(p.resolve().parts) > 1}
        tops |= {Path("/", p.name) for p in Path("/").iterdir() if not p.is_symlink()}
        tops |= {p.resolve() for p in Path("/").iterdir() if p.is_symlink()}
        tops |= {Path(p) for p in ("/tmp", "/home", "/root", "/srv", "/mnt", "/media", "/opt", "/var/tmp")}
        covers = sorted(p for p in tops if p.is_dir() and len(p.parts) > 1
                        and (p.parts[1] not in SYSTEM_FOLDERS or p == Path("/var/tmp")))
        needed = [p for p in dict.fromkeys(needed) if p.is_dir() and any(c in p.parents for c in covers)]
        if self.uid is not None:  # as root: a folder of its own in the system's /run
            stage = Path("/run") / f"gandalf-stage-{self.uid}"
            stage.mkdir(exist_ok=True)
        else:  # in a user namespace, which may not create one there: /run itself, covered for the while
            stage = Path("/run")
        lines = ["set -e", f"mount -t tmpfs -o size=64k,mode=0700 gandalf-stage '{stage}'"]
        writable = [private, *([self.shader_cache] if self.shader_cache is not None else [])]
        keep = [*needed, *writable]
        for i, path in enumerate(keep):
            lines += [f"mkdir '{stage}/{i}'", f"mount --bind '{path}' '{stage}/{i}'"]
        lines += [f"mount -t tmpfs -o size=1m,mode=0755 gandalf-cover '{c}'" for c in covers]
        for i, path in enumerate(keep):
            lines += [f"mkdir -p '{path}'", f"mount --bind '{stage}/{i}' '{path}'"]
            if path not in writable:
                lines.append(f"mount -o remount,bind,ro '{path}'")
        lines += [f"mount -o remount,ro '{c}'" for c in covers]
        # Shared memory of its own: the machine's /dev/shm is writable by every user (a channel between sandboxes).
        lines += ["[ ! -d /dev/shm ] || mount -t tmpfs -o size=64m,mode=1777 gandalf-shm /dev/shm"]
        lines += [f"umount -l '{stage}'", "set +e", ""]
        return "\n".join(lines), keep

    def _start(self) -> None:
        self.private = self._lay_out()
        to_child_r, to_child_w = os.pipe()
        from_child_r, from_child_w = os.pipe()
        env = {"PATH": os.environ.get("PATH", "/usr/bin:/bin"), "HOME": str(self.private / "home"),
               "TMPDIR": str(self.private / "tmp"), "LANG": "C.UTF-8", "OPENBLAS_NUM_THREADS": "1",
               "OMP_NUM_THREADS": "1", "MKL_NUM_THREADS": "1",
               "MESA_SHADER_CACHE_DIR": str(self.shader_cache or self.private / "home" / ".cache"), **self.env}
        with open(self.private / "stderr.txt", "wb") as err:
            self.proc = subprocess.Popen(
                self._command(self.private, to_child_r, from_child_w), cwd=self.private, env=env,
                stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL, stderr=err, pass_fds=(to_child_r, from_child_w),
                start_new_session=True)
        os.close(to_child_r)
        os.close(from_child_w)
        self._to_child, self._from_child = to_child_w, from_child_r
        self.generation += 1
        self.imported = set()
        self.callables: list[Callable[..., Any]] = []  # the grader's functions the student's code may call back
        self._sent: set[int] = set()  # the recipes this process has rebuilt (by number)

    def stop(self) -> None:
        """End the sandboxed process, every process of its user, and remove its folder."""
        if self.proc is not None:
            try:
                os.killpg(self.proc.pid, signal.SIGKILL)
            except (ProcessLookupError, PermissionError):
                pass
            self.proc.wait()
            if self.uid is not None:  # processes that left the group (setsid) still have the uid
                subprocess.run(["kill", "-KILL", "--", "-1"], user=self.uid, group=self.uid,
                               stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, check=False)
            for fd in (self._to_child, self._from_child):
                os.close(fd)
            self.proc = None
        if self.uid is not None:
            try:
                (Path("/run") / f"gandalf-stage-{self.uid}").rmdir()
            except OSError:
                pass
        if self.private is not None:
            shutil.rmtree(self.private, ignore_errors=True)
            self.private = None

    # --- requests -------------------------------------------------------------------------------------
    def request(self, message: dict[str, Any], *, label: str | Callable[[], str], budget: float, key: str,
                objects: Callable[[str, dict[str, Any]], Any] | None = None,
                encode_objects: Callable[[Any], Any] | None = None, hang: str = "a loop that never ends?",
                crash: str = "") -> Any:
        """Send ``message``; the reply's ``ok`` value (decoded with ``objects``) or its ``error``/``warnings`` as
        they came. ``key`` names the function for the memory of hung ones; ``label`` (or what it returns, made only
        for a message) says the call in messages."""
        package = str(message["package"])
        key = f"{package}:{key}"
        if key in self.failed:
            raise SandboxFailure(self.failed[key])
        if package in self.import_errors:
            raise SandboxFailure(self.import_errors[package])
        if self.proc is None:
            self._start()
        if message["package"] is not None and package not in self.imported:
            try:
                self._exchange({"op": "import", "package": package}, STARTUP_BUDGET + budget, None, None)
                self.imported.add(package)
            except (wire.Timeout, EOFError, wire.WireError, OSError) as exc:
                why = (f"did not finish in {STARTUP_BUDGET + budget:g} s" if isinstance(exc, wire.Timeout)
                       else f"ended its process{self._last_words()}")
                self.import_errors[package] = f"importing your {package} {why}"
                self.stop()
                raise SandboxFailure(self.import_errors[package]) from None
        def said() -> str:
            return label() if callable(label) else label

        try:
            return self._exchange(message, budget, objects, encode_objects)
        except wire.Timeout:
            self.failed[key] = f"{said()} did not return within {budget:g} s ({hang})"
        except (EOFError, wire.WireError, OSError) as exc:
            try:
                status = self.proc.wait(timeout=2) if self.proc else None
            except subprocess.TimeoutExpired:
                status = None
            ended = f"{said()} ended its process (exit status {status}){crash}{self._last_words()}"
            self.failed[key] = ended if isinstance(exc, (EOFError, OSError)) else (
                f"{said()} sent a reply that cannot be read ({exc})")
        except BaseException:  # the test's own time limit (or ^C) while waiting: the process is mid-call, end it
            self.failed[key] = f"{said()} was stopped by the test's time limit"
            self.stop()
            raise
        self.stop()
        raise SandboxFailure(self.failed[key])

    def _last_words(self, limit: int = 300) -> str:
        """The end of what the ended process wrote to stderr (capped), for the failure message."""
        try:
            with open(self.private / "stderr.txt", "rb") as f:  # type: ignore[operator]
                f.seek(max(0, os.fstat(f.fileno()).st_size - limit))
                text = f.read().decode(errors="replace").strip()
        except OSError:
            return ""
        return f"; its last words: {text[-limit:]}" if text else ""

    def _exchange(self, message: dict[str, Any], budget: float, objects: Any, encode_objects: Any) -> Any:
        callables = self.callables  # kept for the process's life: a function patched in stays callable

        def number(fn: Callable[..., Any]) -> int | dict[str, Any]:
            if id(fn) not in self._recipes or self._recipes[id(fn)][0] is not fn:
                made = recipe(fn)
                # the function is kept (its id stays its own); its recipe is numbered, sent whole once per process
                self._recipes[id(fn)] = (fn, made and {**made, "id": next(_recipe_numbers)})
            rebuilt = self._recipes[id(fn)][1]
            if rebuilt is not None:
                if rebuilt["id"] in self._sent:  # the process has it already: its number alone
                    return {"id": rebuilt["id"]}
                self._sent.add(rebuilt["id"])
                return rebuilt
            callables.append(fn)
            return len(callables) - 1

        wire.write_frame(self._to_child, wire.pack(message, encode_objects, number))
        deadline = time.monotonic() + budget if budget > 0 else None
        while True:
            data, blobs = wire.read_frame(self._from_child, deadline)
            try:
                reply = wire.decode_value(data, blobs, objects)
            except (wire.WireError, ValueError, TypeError) as exc:  # read whole: the process can go on
                message = f"returned {exc}, which the grader cannot use"
                return {"error": {"types": ["TypeError"], "name": "TypeError", "message": message[:500]}}
            if not isinstance(reply, dict):
                raise wire.WireError("not a reply")
            if "callback" not in reply:
                return reply
            try:
                answer = {"ok": callables[int(reply["callback"])](*reply.get("args", ()))}
            except Exception as exc:  # noqa: BLE001 - the grader's own function failed on the student's input
                answer = {"error": f"{type(exc).__name__}: {exc}"[:500]}
            wire.write_frame(self._to_child, wire.pack(answer, encode_objects, number))
