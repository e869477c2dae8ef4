# SPDX-License-Identifier: BSD-3-Clause
"""The mros2 PC target: the user's mros2 (with its embeddedRTPS) and app,
unchanged, on a PC.

``genmros mros2-pc`` builds them (:mod:`.build`) with the stand-ins beside
this package for the board's CMSIS-RTOS2, lwIP (its sys_arch, raw UDP API
and tcpip thread) and network start-up, and runs the program on a network
of its own against ROS 2 nodes on this PC (:mod:`.network`); docs/mros2.md,
"Your mros2 app on your PC", says what each stand-in does and how it
differs from a board.
"""
