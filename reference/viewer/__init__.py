"""The run viewer: a replayed trace stepped through in the browser (``topomark view``).

:mod:`.frames` replays a trace on its world and takes one frame per record (the robot's true pose, the markers,
the map S, the kind of walk of each move); :mod:`.page` writes them as one self-contained HTML file with the
package's ``viewer.js``, ``panels.js``, ``viewer.css`` and ``body.html``; :mod:`.world_of_trace` rebuilds the world
from a trace's own final map when none is given.
"""
