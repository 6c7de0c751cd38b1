"""The oracle: other implementations judged by topomark's checker (``spec/protocol.md``).

:mod:`.protocol` (messages), :mod:`.snapshot_wire` ((S, U) on the wire), :mod:`.marker_messages`
(marker operations on the wire), :mod:`.peer` and :mod:`.process_tree` (the program under test),
:mod:`.run_external` (topomark plays the world), :mod:`.drive` (topomark explores a provider's world),
:mod:`.conformance` (the versioned suite); ``examples/`` holds runnable clients and a provider.
"""
