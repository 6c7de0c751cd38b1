"""The engine's equality comparison as tasks on disk, so that an hour-long comparison resumes where it stopped
(thesis §3.3).

``python -m topomark.reference.engine.equality ... --shards DIR`` keeps, in one
directory (``topomark/equality@1``)::

    manifest.json     the parameters and a digest of the code that decides a run (written once)
    task-T.json       task T's counts and disagreements (written when the task ends, atomically)

Every file is a record sealed with its checksum
(:func:`topomark.proofs.census_shards.seal`) and a task file names the
manifest's checksum, so a resume keeps only the finished tasks of this
comparison, written by this code; a task file that is missing, damaged or of
another comparison runs again.  A directory of another comparison (other
options) or of other code is bad input (exit 2): the counts of two codes are
never added up.

>>> import tempfile; from pathlib import Path
>>> root = Path(tempfile.mkdtemp())
>>> store = EqualityStore(root, {"max_vertices": 3})
>>> store.save(0, {"counts": {"3": 4}}); EqualityStore(root, {"max_vertices": 3}).finished(1)[0]["counts"]
{'3': 4}
"""

from __future__ import annotations

from pathlib import Path
from typing import Any, Callable

from topomark.proofs.census_integrity import Damaged, read_capped, read_record_text, source_digest
from topomark.proofs.census_shards import seal, write_json
from topomark.spec.errors import InvalidInput

__all__ = ["FORMAT", "CODE_PACKAGES", "CODE_MODULES", "EqualityStore", "code_digest"]

FORMAT = "topomark/equality@1"
CODE_PACKAGES = ("topomark.spec", "topomark.reference.explorers", "topomark.reference.algorithms",
                 "topomark.reference.run", "topomark.reference.engine")
"""The reference, the engine and the comparison: a change to any makes earlier task files another code's."""
CODE_MODULES = ("topomark.proofs.census_map", "topomark.proofs.enumerate", "topomark.proofs.world_batches",
                "topomark.proofs.orbit_kernel", "topomark.proofs.start_orbits", "topomark.proofs.world_arrays")
"""The modules of proofs/ that decide which worlds and starts are compared."""


def code_digest() -> str:
    return f"equality code {source_digest(CODE_PACKAGES, CODE_MODULES)}"


def _read(path: Path) -> dict[str, Any]:
    data = read_capped(path)
    try:
        return read_record_text(data.decode("utf-8"))
    except UnicodeDecodeError:
        raise Damaged("it is not UTF-8 text") from None


class EqualityStore:
    """One comparison's directory: its manifest (read on resume, else written) and its finished tasks."""

    def __init__(self, root: Path, params: dict[str, Any]):
        self.root = root
        try:
            root.mkdir(parents=True, exist_ok=True)
        except OSError as e:
            raise InvalidInput(f"--shards {str(root)!r} cannot be made: {e.strerror or e}") from None
        path = root / "manifest.json"
        if not (path.exists() or path.is_symlink()):
            self.manifest = seal({"format": FORMAT, "code": code_digest(), "params": params})
            write_json(path, self.manifest)
            return
        try:
            self.manifest = _read(path)
        except Damaged as e:
            raise InvalidInput(f"{path}: damaged: {e}; remove {root} or choose an empty directory") from None
        if self.manifest.get("format") != FORMAT:
            raise InvalidInput(f"{path}: not a {FORMAT} manifest; choose an empty directory")
        if self.manifest.get("params") != params or self.manifest.get("code") != code_digest():
            raise InvalidInput(f"--shards {root} holds another comparison ({self.manifest.get('params')}, "
                               f"{self.manifest.get('code')}); use an empty directory, or the same options and code")

    def path(self, task: int) -> Path:
        return self.root / f"task-{task}.json"

    def finished(self, tasks: int, note: Callable[[str], None] = lambda _: None) -> dict[int, dict[str, Any]]:
        """The results of the tasks below ``tasks`` whose files pass their checks; a damaged one is noted and
        will run again."""
        good = {}
        for t in range(tasks):
            path = self.path(t)
            if not (path.exists() or path.is_symlink()):
                continue
            try:
                record = _read(path)
                if record.get("comparison") != self.manifest["checksum"] or record.get("task") != t:
                    raise Damaged("it belongs to another comparison or task")
            except (Damaged, InvalidInput) as e:
                note(f"equality: {path}: {e}; running task {t} again")
                continue
            good[t] = record["result"]
        return good

    def save(self, task: int, result: dict[str, Any]) -> None:
        write_json(self.path(task), seal({"comparison": self.manifest["checksum"], "task": task, "result": result}))
