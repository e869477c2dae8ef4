# SPDX-License-Identifier: BSD-3-Clause
"""copyToFragBuf continues where the last fragment stopped, kept in the
counters mros2's messages have anyway (cntSub, idxSerialized): every cut
of every type's image comes out as copyToBuf writes it, and the count's
contract holds (copyToBuf wrote all, resetCount starts over, even in the
middle), on the host and on big-endian s390x. How fast: bench/mros2/fragment_speed.py."""

import random
import subprocess

import pytest

from support.checkout import run_genmros
from testing import fastcdr, ros2_messages

from support.mros2_corpus import ECHO_TARGETS
from testing.ros_paths import prefix_arguments, ros2_prefixes

# Fragment sizes for the echo program, which drives copyToFragBuf as mros2's
# runtime does: the first fragment carries the 4-byte header, the last is
# padded to 4 bytes of its own, so the sizes are multiples of 4. They cut
# inside 8-byte numbers, strings and padding runs at every such phase.
FRAGMENT_SIZES = (8, 12, 16, 20, 24, 28, 36, 60, 64)

PROGRAM = r'''
#include <stdio.h>

#include <vector>

#include "test_interface_files/msg/multi_nested.hpp"
#include "test_interface_files/msg/unbounded_sequences.hpp"

using test_interface_files::msg::MultiNested;
using test_interface_files::msg::UnboundedSequences;

typedef std::vector<uint8_t> Bytes;

static void fill(UnboundedSequences& m, unsigned count) {
  m.string_values.resize(count);
  m.basic_types_values.resize(count);
  m.float64_values.resize(count);
  m.bool_values.resize(count);
  for (unsigned i = 0; i < count; ++i) {
    m.string_values[i] = std::string(i % 23, 'a' + i % 26);
    m.basic_types_values[i].int64_value = i;
    m.float64_values[i] = i * 0.5;
    m.bool_values[i] = i % 3 == 0;
  }
}

static Bytes image(UnboundedSequences& m) {
  Bytes bytes(m.calcRawTotalSize());
  m.copyToBuf(bytes.data());
  m.resetCount();
  return bytes;
}

// calls copyToFragBuf of size bytes each, until all is written or calls run out.
static Bytes fragments(UnboundedSequences& m, uint32_t size, int calls) {
  Bytes sent;
  uint8_t fragment[64];
  for (; calls > 0; --calls) {
    UnboundedSequences::FragCopyReturnType done = m.copyToFragBuf(fragment, size);
    sent.insert(sent.end(), fragment, fragment + done.second);
    if (done.first) break;
  }
  return sent;
}

static void check(bool ok, const char* what) { printf("%s %s\n", ok ? "ok" : "FAILED", what); }

int main() {
  check(sizeof(mros2_wire::Message<MultiNested>) == 3 * sizeof(uint32_t),
        "where the fragments stopped takes no room beside mros2's three counters");
  UnboundedSequences m;
  fill(m, 40);
  const Bytes all = image(m);

  m.copyToBuf(Bytes(all.size()).data());
  UnboundedSequences::FragCopyReturnType after = m.copyToFragBuf(Bytes(64).data(), 64);
  check(after.first && after.second == 0 && m.getPubCnt() == all.size(),
        "after copyToBuf, copyToFragBuf writes nothing and says all is written");
  m.resetCount();

  Bytes first = fragments(m, 7, 5);
  check(first == Bytes(all.begin(), all.begin() + 35), "five 7-byte fragments: the first 35");
  m.resetCount();
  check(fragments(m, 7, 1 << 30) == all, "resetCount in the middle starts over");
  check(fragments(m, 7, 1).empty() && m.getPubCnt() == all.size(),
        "after the last fragment, another writes nothing");
  check(m.calcTotalSize() == 4 + all.size() + (4 - all.size() % 4) % 4 && m.getPubCnt() == 0,
        "calcTotalSize after a whole publication starts the count over");
  check(fragments(m, 64, 1 << 30) == all, "published again: the same bytes");
  m.resetCount();

  MultiNested nested;
  nested.unbounded_sequence_of_unbounded_sequences.resize(3);
  for (int i = 0; i < 3; ++i) fill(nested.unbounded_sequence_of_unbounded_sequences[i], 5 + i);
  Bytes nested_all(nested.calcRawTotalSize());
  nested.copyToBuf(nested_all.data());
  nested.resetCount();
  Bytes nested_sent;
  for (;;) {
    uint8_t fragment[3];
    MultiNested::FragCopyReturnType done = nested.copyToFragBuf(fragment, 3);
    nested_sent.insert(nested_sent.end(), fragment, fragment + done.second);
    if (done.first) break;
  }
  check(nested_sent == nested_all, "MultiNested (three levels) in 3-byte fragments");
  return 0;
}
'''


@pytest.fixture(scope='module')
def export(tmp_path_factory):
    root = str(tmp_path_factory.mktemp('fragment_cursor_export'))
    run_genmros('mros2-export', *prefix_arguments(ros2_prefixes()), '-o', root,
                '--type', 'test_interface_files/msg/MultiNested',
                '--type', 'test_interface_files/msg/UnboundedSequences')
    return root


TARGETS = ['host', pytest.param('s390x', marks=[pytest.mark.slow, pytest.mark.needs_qemu])]


@pytest.mark.parametrize('target', TARGETS)
def test_the_count_contract_holds(export, tmp_path, target):
    runner, compiler = ECHO_TARGETS[target]
    source = tmp_path / 'cursor.cpp'
    source.write_text(PROGRAM)
    program = str(tmp_path / 'cursor')
    subprocess.run(list(compiler) + ['-std=c++11', '-O2', '-Wall', '-Wextra', '-pedantic',
                                     '-Werror', '-I', export, str(source), '-o', program]
                   + (['-static'] if runner else []), check=True)
    lines = subprocess.run(list(runner) + [program], capture_output=True, text=True,
                           check=True).stdout.splitlines()
    assert [line for line in lines if line.startswith('FAILED')] == []
    assert len([line for line in lines if line.startswith('ok')]) == 8


def _samples(corpus, fastcdr_program, seed):
    rng = random.Random(seed)
    instances = [(index, ros2_messages.random_value(message, rng))
                 for index, message in enumerate(corpus.messages) for _ in range(2)]
    references = fastcdr.encode_many(fastcdr_program, [
        ros2_messages.fastcdr_ops(corpus.messages[i], value) for i, value in instances])
    return [(index, size, reference) for (index, _), reference in zip(instances, references)
            for size in FRAGMENT_SIZES]


@pytest.mark.parametrize('target', TARGETS)
def test_every_cut_of_every_image_comes_out_as_copytobuf_writes_it(
        test_interface_corpus, rosbags_corpus, fastcdr_program, target):
    for number, corpus in enumerate((test_interface_corpus, rosbags_corpus)):
        samples = _samples(corpus, fastcdr_program, seed=40 + number)
        for (index, size, reference), result in zip(samples, corpus.echo(target).run(samples)):
            name = '%s in %d-byte fragments' % (corpus.messages[index].full_name, size)
            assert result.raw == reference, name
            assert result.fragmented == result.whole, name
            assert result.again == result.whole, name
