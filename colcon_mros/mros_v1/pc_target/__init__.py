"""The mROS v1 PC target: the user's mROS v1 library and app on a PC.

- ``build``: ``genmros mros-v1-pc``, the app's variables asked of make,
  the build in steps (library, app, link), ``--sanitize``
- ``asp_cfg``: TOPPERS/ASP's configurator, app.cfg to kernel tables
- ``ros_graph``: a built app run beside real ROS nodes on this machine
  (rosmaster on a free loopback port, the app as a board with its pins in
  files), as the paper's evaluation, the tests and the benchmarks run it
- ``mros_v1_pc.mk`` and the C/C++ stand-ins beside it (``asp/``, ``lwip/``,
  ``mbed/``, ``config/``, ``cfg/``): see README.md here for what each stands
  in for and how it differs from the board
"""
