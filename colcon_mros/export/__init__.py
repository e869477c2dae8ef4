"""Exports: the headers one firmware needs, and the export dir.

- firmware_export: ``genmros export``, the types a firmware names and every
  type they contain, with the per-firmware aggregates (``ExportRequest``)
- export_dir: the export dir of catkin and colcon, its only owner (layout,
  type list, mros_export.cmake, claims)

Imports the generator and colcon_mros.errors, nothing above.
"""
