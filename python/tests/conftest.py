"""Shared by the Python module's tests. ctest runs them with PYTHONPATH at
build/python and APPRENTICE_SOURCE_DIR / APPRENTICE_BINARY set
(python/CMakeLists.txt); run by hand:

    PYTHONPATH=build/python /usr/bin/python3 -m pytest python/tests
"""
import os
import pathlib

SOURCE_DIR = pathlib.Path(os.environ.get("APPRENTICE_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
BINARY = pathlib.Path(os.environ.get("APPRENTICE_BINARY", SOURCE_DIR / "build" / "apprentice"))
SCENARIOS = SOURCE_DIR / "data" / "scenarios"
KITCHEN = SCENARIOS / "tidy-kitchen.yaml"
