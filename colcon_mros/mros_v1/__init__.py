"""The mROS v1 library: everything genmros knows of it, in one place.

What the library is, which the export uses: its settings read from its
headers (``settings``), the rule table of what a type needs of each setting
(``rules``), the fit check (``fit``) and the same rules rendered as the
compile-time check ``mros_v1_fit_check.h`` (``fit_check_header``). What runs
it, on top of the export: the fit report of an app or an export dir
(``report``, ``genmros mros-v1-fit``) and the PC target (``pc_target``,
``genmros mros-v1-pc``). The library's task stacks and the patches for the
user's checkout belong here too.
"""
