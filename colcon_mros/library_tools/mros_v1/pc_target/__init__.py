# SPDX-License-Identifier: BSD-3-Clause
"""The mROS v1 PC target: the user's mROS v1 library and app, unchanged, on a PC.

``genmros mros-v1-pc`` builds them with the stand-ins beside this package
for the board's TOPPERS/ASP, lwIP and mbed (README.md here says what each
stands in for and how it differs from the board).
"""
