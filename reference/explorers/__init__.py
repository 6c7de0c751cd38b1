"""Explorers: one module per thesis algorithm family, each seeing only the robot interface.

Every module in this folder is held by ``tests/test_wall.py`` to import
nothing that can reach the world, the simulator or the checker.
"""
