@# SPDX-License-Identifier: BSD-3-Clause
@# One message class: its members, and mros2's calls through mros2_wire::Message.
@[for line in msg.comment]@
// @(line)
@[end for]@
class @(msg.name) : public mros2_wire::Message<@(msg.name)>
{
public:
@[for constant in msg.constants]@
  static constexpr @(constant.type) @(constant.name) = @(constant.literal);
@[end for]@
@[for member in msg.members]@
@[for line in member.comment]@
  // @(line)
@[end for]@
  @(member.type) @(member.name)@(member.initializer);
@[end for]@

  template <class Writer>
  void writeTo(Writer& writer) const
  {
@[for member in msg.members]@
    mros2_wire::write(writer, @(member.name));
@[end for]@
  }

  bool readFrom(mros2_wire::Reader& reader)
  {
@[for member in msg.members]@
    if (!mros2_wire::read(reader, @(member.name))) return false;
@[end for]@
    return true;
  }
};
