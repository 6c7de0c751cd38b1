"""Explorers: one module per thesis algorithm family or technique, each seeing only the robot interface.

* :mod:`.contract` — the explorer contract every explorer keeps (``start``, ``step``, ``done``, ``models``;
  ``S``, ``position``, ``iterations``), a :class:`typing.Protocol`;
* :mod:`.walker` — what the families share: the contract's state, recording a step, walking S, loop and
  non-loop augmentation (§3.1.3);
* :mod:`.algorithm31` — Algorithm 3.1 (§3.3): the loop body as a template with named hooks;
* :mod:`.lighthouses` — how v0 is established and recognised (§3.3, §6.1, §6.2);
* :mod:`.enhanced`, :mod:`.compositions` — Chapter 4's enhancements as compositions of techniques:
  :mod:`.overlap` (Enhancement-1), :mod:`.tracing` (Enhancements 2 and 3), :mod:`.records` (the store T),
  :mod:`.expansion` (Enhancements 4 and 5), over the :mod:`.execution_trie` of an iteration.

``tests/test_wall.py`` lists this folder and holds every module in it to
importing nothing that can reach the world, the simulator or the checker.
"""
