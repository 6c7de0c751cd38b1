"""A checked exploration: world → simulator → robot → explorer → checker → outcome.

:mod:`.simulator` holds the world (the truth) and hands the explorer only its robot;
:mod:`.checker` checks the invariants the algorithm's registry entry names after every step;
:mod:`.map_check` judges a finished map; :mod:`.explore` wires them together.
"""
