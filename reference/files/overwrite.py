"""What a command does with an output path that is already there: one rule, for every command that writes.

:data:`RULE` states it (the command-line reference prints it); :func:`claim_file` and :func:`claim_dir`
apply it, before any work starts, so a refused command has written nothing:

* an output file that exists (a regular file: ``--trace``, ``--map``, ``-o FILE``) or an output directory
  that is not empty (``-o DIR``, ``--models``, ``conformance export DIR``) is refused, exit 2, with one
  message naming the option, the path and ``--force``;
* with ``--force`` the file is overwritten, and the directory is written into, its files of the same names
  replaced; what a command lists as its own (``replace``: an earlier suite, earlier models) is removed
  first, so old and new are never mixed;
* the Python API's writers (``explore(trace=...)``, ``save_world``) follow the same rule with a ``force``
  keyword, and the message names the keywords (``trace='run.jsonl': ... give force=True ...``);
* a device or a pipe (``/dev/null``, ``/dev/stdout``) is written as always; an empty path is exit 2;
* directories that are inputs as well as outputs are not claimed: ``bench -o DIR`` and ``--shards DIR``
  resume from what is in them.

Examples
--------
>>> import tempfile, pathlib
>>> d = pathlib.Path(tempfile.mkdtemp()); (d / "map.json").write_text("{}")
2
>>> claim_file(str(d / "map.json"), "--map", force=False)  # doctest: +ELLIPSIS
Traceback (most recent call last):
...
topomark.spec.errors.InvalidInput: --map .../map.json: the file exists; give --force to overwrite it
>>> claim_file(str(d / "map.json"), "--map", force=True)
>>> claim_dir(str(d), "-o", force=False)  # doctest: +ELLIPSIS
Traceback (most recent call last):
...
topomark.spec.errors.InvalidInput: -o ...: the directory is not empty; give --force to write into it
"""

from __future__ import annotations

import shutil
from pathlib import Path

from topomark.spec.errors import InvalidInput
from topomark.spec.spelling import in_python

from topomark.reference.files.outputs import check_output

__all__ = ["RULE", "named_path", "claim_file", "claim_dir"]

RULE = (
    "A command never writes over what is already there unless told to. An output file that exists (`--trace FILE`, "
    "`--map FILE`, `-o FILE`) and an output directory that is not empty (`-o DIR` of `search` and `worst-case`, "
    "`explore --models DIR`, `conformance export DIR`) are refused before any work starts: exit 2, one message "
    "naming the path and `--force`, nothing written. With `--force` the file is overwritten and the directory is "
    "written into, its files of the same names replaced; `conformance export` and `explore --models` first remove "
    "the suite or the models written there before, so old and new are never mixed (a suite directory must hold "
    "nothing else: anything else in it is still refused). A device or a pipe (`/dev/null`, `/dev/stdout`) is "
    "written as always. An empty path is exit 2. The directories that are inputs as well as outputs are reused "
    "without `--force`, on purpose: `bench -o DIR` (a sweep resumes from its `runs.csv` and writes its reports "
    "again beside it), `census --shards DIR` and `worst-case --shards DIR` (a run resumes from the finished "
    "shards).")

def named_path(path: str | Path | None, flag: str) -> Path | None:
    """``path`` as a Path (None: not given); an empty path is InvalidInput naming ``flag``."""
    if path is None:
        return None
    if not str(path).strip():
        raise InvalidInput(f"{flag}: the path is empty")
    return Path(path)


def claim_file(path: str | Path | None, flag: str, force: bool) -> None:
    """Refuse (InvalidInput) an output file ``path`` given as ``flag`` that exists, unless ``force``; then check
    it can be written (:func:`~topomark.reference.files.outputs.check_output`).  ``None``: not asked for."""
    p = named_path(path, flag)
    if p is None:
        return
    if p.is_file() and not force:
        if in_python():  # the Python API: name the keyword arguments, as the caller typed them
            raise InvalidInput(f"{flag}={str(path)!r}: the file exists; give force=True to overwrite it")
        raise InvalidInput(f"{flag} {path}: the file exists; give --force to overwrite it")
    check_output(p)


def claim_dir(path: str | Path | None, flag: str, force: bool, replace: tuple[str, ...] = (),
              alone: bool = False) -> None:
    """Refuse (InvalidInput) an output directory ``path`` given as ``flag`` that is not empty, unless ``force``.

    With ``force``, the entries matching a glob pattern of ``replace`` (what the command writes there) are
    removed first; ``alone``: the directory may hold nothing else, so anything else is refused even then."""
    p = named_path(path, flag)
    if p is None or not p.exists():
        return
    if not p.is_dir():
        raise InvalidInput(f"{flag} {path}: it exists and is not a directory")
    entries = sorted(p.iterdir())
    if not entries:
        return
    if not force:
        raise InvalidInput(f"{flag} {path}: the directory is not empty; give --force to write into it")
    own = {e for pattern in replace for e in p.glob(pattern)}
    others = [e for e in entries if e not in own]
    if alone and others:
        raise InvalidInput(f"{flag} {path}: it holds {others[0].name}, which the command does not write; "
                           "--force replaces only an earlier output of the command")
    for entry in sorted(own):
        try:
            if entry.is_dir() and not entry.is_symlink():
                shutil.rmtree(entry)
            else:
                entry.unlink()
        except OSError as exc:
            raise InvalidInput(f"{flag} {path}: cannot remove {entry.name}: {exc.strerror or exc}") from None
