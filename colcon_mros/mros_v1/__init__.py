"""The mROS v1 library: everything genmros knows of it, in one place.

What the library is (its settings, the rule table of what a message type
needs of them, the fit check and its compile-time rendering), which the
export uses; and what runs it on top of the export (the fit report, the PC
target). docs/design.md maps the modules and their two layers.
"""
