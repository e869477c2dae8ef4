"""The generator: ROS 1 .msg/.srv files to mROS C++ headers.

parse (genmsg specs, errors by file and line) -> model (the structure of
types, with identity: MD5 sums and definition texts, and storage: heap or
bounded) -> cpp (the model's C++ names) -> render (the empy templates in
templates/, logic-free, beside the static support headers in support/) ->
output (atomic writes). workspace finds packages and their message
directories; defaults holds the choices every front end offers.

It knows no build tool and no library setting. It imports only itself and
colcon_mros.errors.
"""
