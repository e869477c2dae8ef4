"""The mROS v1 library: everything genmros knows of it, in one place.

What the library is (its settings, the rule table of what a message type
needs of them, the fit check and its compile-time rendering, the
per-firmware aggregates and on-board delivery, its apps), which the export
uses; and what runs it on top of the export (the fit flow, the fit report,
the PC target, the patch set). docs/design.md maps the modules and their
layers.
"""
