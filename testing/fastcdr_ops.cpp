// SPDX-License-Identifier: BSD-3-Clause
// The reference CDR serializer of the byte-exact tests: Debian's Fast-CDR
// 1.0.26 (libfastcdr-dev), driven by a type-agnostic list of ops, one
// Fast-CDR call per op. testing/fastcdr.py builds and runs it.
//
// The stream is XCDR1 little endian as ROS 2 and Fast DDS write it: the
// encapsulation header 00 01 00 00 (serialize_encapsulation() of a DDS_CDR
// Cdr), then the data, aligned relative to the first byte after the header.
//
//   fastcdr_ops encode   stdin: one op per line ("kind value");
//                        stdout: the whole buffer, header included, as one
//                        lowercase hex line.
//   fastcdr_ops decode   stdin: the buffer's hex (with the header) on the
//                        first line, then one kind per line; stdout: one
//                        "kind value" line per op, in the form encode takes.
//
// A Fast-CDR exception prints "error <what()>" to stdout (after the ops
// decoded before it) and exits 1; input this program cannot parse is reported
// on stderr with exit status 2.
//
// Ops and their text values:
//   bool      0 or 1                  serialize(bool)
//   char      0..255                  serialize(char)
//   octet     0..255                  serialize(uint8_t)
//   int8 uint8 int16 uint16 int32 uint32 int64 uint64
//             decimal                 serialize(<that type>)
//   float32 float64
//             C99 hex float (%a), inf, -inf, nan, or nan(0xM) / -nan(0xM)
//             where M is the whole mantissa field (quiet bit included): a NaN
//             keeps its exact bits both ways. Decimal is accepted on input.
//   string    hex of the bytes        serialize(const std::string&)
//   wstring   hex of the UTF-32LE code units, 8 hex digits each
//                                     serialize(const std::wstring&)
//   count     decimal                 serialize(uint32_t): a sequence's length
// An empty string or wstring is "string" or "string " (empty hex).
//
// What Fast-CDR 1.0.26 writes (checked in its Cdr.h and src/cpp/Cdr.cpp at
// tag v1.0.26, and pinned by tests/mros2/test_fastcdr_reference.py):
// - char, int8, uint8 and octet: one byte, no alignment (all go through
//   serialize(char)); bool: one byte 0 or 1, and deserialize(bool) refuses
//   any other byte (BadParamException).
// - std::string: serialize(const std::string&) is serialize(s.c_str()): a
//   uint32 length strlen + 1, then the bytes and one NUL. The string ends at
//   its first NUL byte ("a\0b" is written as "a"); "" is length 1 and a NUL.
//   Reading drops one trailing NUL if there is one.
// - std::wstring: serialize(s.c_str()) as well: a uint32 count of wchar_t
//   (wcslen, not bytes, no terminator), then each wchar_t as 4 bytes (the
//   4-byte wchar_t of Linux, in the stream's byte order). No alignment after
//   the length, which leaves the elements 4-aligned anyway. It ends at its
//   first L'\0'; "" is a count of 0 and nothing more.
// - A std::vector's length is written as int32_t; "count" writes uint32_t as
//   rosidl_typesupport_fastrtps does. The bytes are the same.
// - int64, uint64 and float64 align to 8 (DDS_CDR, XCDR1).

#include <fastcdr/Cdr.h>
#include <fastcdr/FastBuffer.h>
#include <fastcdr/exceptions/Exception.h>

#include <cerrno>
#include <cinttypes>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <iostream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>
#include <algorithm>

using eprosima::fastcdr::Cdr;
using eprosima::fastcdr::FastBuffer;

namespace {

static_assert(sizeof(wchar_t) == 4, "wstring ops need Linux' 4-byte wchar_t");

// Input this program cannot parse (not a Fast-CDR refusal): exit status 2.
struct BadInput : std::runtime_error
{
    explicit BadInput(
            const std::string& what)
        : std::runtime_error(what)
    {
    }

};

std::string hex_of(
        const unsigned char* data,
        size_t size)
{
    static const char digits[] = "0123456789abcdef";
    std::string text;
    text.reserve(2 * size);
    for (size_t i = 0; i < size; ++i)
    {
        text += digits[data[i] >> 4];
        text += digits[data[i] & 0xf];
    }
    return text;
}

std::vector<unsigned char> bytes_of_hex(
        const std::string& text)
{
    if (text.size() % 2 != 0)
    {
        throw BadInput("odd number of hex digits: " + text);
    }
    std::vector<unsigned char> bytes;
    for (size_t i = 0; i < text.size(); i += 2)
    {
        std::string pair = text.substr(i, 2);
        if (!isxdigit(static_cast<unsigned char>(pair[0])) ||
                !isxdigit(static_cast<unsigned char>(pair[1])))
        {
            throw BadInput("not hex: " + text);
        }
        bytes.push_back(static_cast<unsigned char>(std::strtoul(pair.c_str(), nullptr, 16)));
    }
    return bytes;
}

// The whole text as a signed integer in [low, high].
long long signed_value(
        const std::string& text,
        long long low,
        long long high)
{
    errno = 0;
    char* end = nullptr;
    long long value = std::strtoll(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || errno == ERANGE || value < low || value > high)
    {
        throw BadInput("not an integer in range: " + text);
    }
    return value;
}

// The whole text as an unsigned integer up to high; strtoull would take "-1"
// as its maximum, so a sign is refused first.
unsigned long long unsigned_value(
        const std::string& text,
        unsigned long long high)
{
    errno = 0;
    char* end = nullptr;
    if (text.empty() || text[0] == '-' || text[0] == '+')
    {
        throw BadInput("not an unsigned integer: " + text);
    }
    unsigned long long value = std::strtoull(text.c_str(), &end, 10);
    if (*end != '\0' || errno == ERANGE || value > high)
    {
        throw BadInput("not an unsigned integer in range: " + text);
    }
    return value;
}

// Floats as their bits, so a NaN's sign and payload survive both ways
// (printf's "nan" would drop them and strtod's "nan(...)" is glibc's own).
template<typename Float, typename Bits, int MantissaBits>
struct FloatText
{
    static Bits bits_of(
            Float value)
    {
        Bits bits;
        std::memcpy(&bits, &value, sizeof bits);
        return bits;
    }

    static Float of_bits(
            Bits bits)
    {
        Float value;
        std::memcpy(&value, &bits, sizeof value);
        return value;
    }

    static std::string format(
            Float value)
    {
        char text[64];
        if (std::isnan(value))
        {
            Bits bits = bits_of(value);
            Bits mantissa = bits & ((Bits(1) << MantissaBits) - 1);
            bool negative = (bits >> (8 * sizeof(Bits) - 1)) != 0;
            std::snprintf(text, sizeof text, "%snan(0x%llx)", negative ? "-" : "",
                    static_cast<unsigned long long>(mantissa));
        }
        else if (std::isinf(value))
        {
            std::snprintf(text, sizeof text, "%s", value < 0 ? "-inf" : "inf");
        }
        else
        {
            std::snprintf(text, sizeof text, "%a", static_cast<double>(value));
        }
        return text;
    }

    static Float parse(
            const std::string& text)
    {
        bool negative = !text.empty() && text[0] == '-';
        std::string unsigned_text = negative ? text.substr(1) : text;
        if (unsigned_text == "nan")
        {
            Float value = std::numeric_limits<Float>::quiet_NaN();
            return negative ? -value : value;
        }
        if (unsigned_text.compare(0, 4, "nan(") == 0 && unsigned_text.back() == ')')
        {
            std::string digits = unsigned_text.substr(4, unsigned_text.size() - 5);
            errno = 0;
            char* end = nullptr;
            unsigned long long mantissa = std::strtoull(digits.c_str(), &end, 16);
            Bits mantissa_mask = (Bits(1) << MantissaBits) - 1;
            if (digits.empty() || *end != '\0' || errno == ERANGE || mantissa == 0 ||
                    mantissa > mantissa_mask)
            {
                throw BadInput("not a NaN mantissa: " + text);
            }
            Bits exponent_mask = static_cast<Bits>(~mantissa_mask) & static_cast<Bits>(~Bits(0) >> 1);
            Bits sign = negative ? static_cast<Bits>(Bits(1) << (8 * sizeof(Bits) - 1)) : 0;
            return of_bits(static_cast<Bits>(sign | exponent_mask | mantissa));
        }
        errno = 0;
        char* end = nullptr;
        Float value = sizeof(Float) == 4 ? std::strtof(text.c_str(), &end) : std::strtod(text.c_str(), &end);
        if (text.empty() || *end != '\0')
        {
            throw BadInput("not a float: " + text);
        }
        // errno is ERANGE for subnormal results too; those are exact from hex.
        return value;
    }

};

typedef FloatText<float, uint32_t, 23> Float32Text;
typedef FloatText<double, uint64_t, 52> Float64Text;

std::wstring wstring_of_hex(
        const std::string& text)
{
    std::vector<unsigned char> bytes = bytes_of_hex(text);
    if (bytes.size() % 4 != 0)
    {
        throw BadInput("wstring hex is not whole UTF-32LE code units: " + text);
    }
    std::wstring value;
    for (size_t i = 0; i < bytes.size(); i += 4)
    {
        uint32_t unit = bytes[i] | (bytes[i + 1] << 8) | (bytes[i + 2] << 16) |
                (static_cast<uint32_t>(bytes[i + 3]) << 24);
        value += static_cast<wchar_t>(unit);
    }
    return value;
}

std::string hex_of_wstring(
        const std::wstring& value)
{
    std::vector<unsigned char> bytes;
    for (wchar_t character : value)
    {
        uint32_t unit = static_cast<uint32_t>(character);
        for (int shift = 0; shift < 32; shift += 8)
        {
            bytes.push_back(static_cast<unsigned char>(unit >> shift));
        }
    }
    return hex_of(bytes.data(), bytes.size());
}

// "kind value" or "kind" alone (an empty string's value).
void split_op(
        const std::string& line,
        std::string& kind,
        std::string& value)
{
    size_t space = line.find(' ');
    kind = line.substr(0, space);
    value = space == std::string::npos ? "" : line.substr(space + 1);
}

void encode_op(
        Cdr& cdr,
        const std::string& kind,
        const std::string& value)
{
    if (kind == "bool")
    {
        cdr.serialize(unsigned_value(value, 1) != 0);
    }
    else if (kind == "char")
    {
        cdr.serialize(static_cast<char>(unsigned_value(value, 255)));
    }
    else if (kind == "octet" || kind == "uint8")
    {
        cdr.serialize(static_cast<uint8_t>(unsigned_value(value, 255)));
    }
    else if (kind == "int8")
    {
        cdr.serialize(static_cast<int8_t>(signed_value(value, INT8_MIN, INT8_MAX)));
    }
    else if (kind == "int16")
    {
        cdr.serialize(static_cast<int16_t>(signed_value(value, INT16_MIN, INT16_MAX)));
    }
    else if (kind == "uint16")
    {
        cdr.serialize(static_cast<uint16_t>(unsigned_value(value, UINT16_MAX)));
    }
    else if (kind == "int32")
    {
        cdr.serialize(static_cast<int32_t>(signed_value(value, INT32_MIN, INT32_MAX)));
    }
    else if (kind == "uint32" || kind == "count")
    {
        cdr.serialize(static_cast<uint32_t>(unsigned_value(value, UINT32_MAX)));
    }
    else if (kind == "int64")
    {
        cdr.serialize(static_cast<int64_t>(signed_value(value, INT64_MIN, INT64_MAX)));
    }
    else if (kind == "uint64")
    {
        cdr.serialize(static_cast<uint64_t>(unsigned_value(value, UINT64_MAX)));
    }
    else if (kind == "float32")
    {
        cdr.serialize(Float32Text::parse(value));
    }
    else if (kind == "float64")
    {
        cdr.serialize(Float64Text::parse(value));
    }
    else if (kind == "string")
    {
        std::vector<unsigned char> bytes = bytes_of_hex(value);
        cdr.serialize(std::string(bytes.begin(), bytes.end()));
    }
    else if (kind == "wstring")
    {
        cdr.serialize(wstring_of_hex(value));
    }
    else
    {
        throw BadInput("unknown op kind: " + kind);
    }
}

template<typename Value>
Value read(
        Cdr& cdr)
{
    Value value;
    cdr.deserialize(value);
    return value;
}

// The value of one op read from the stream, in the text encode_op takes.
std::string decode_op(
        Cdr& cdr,
        const std::string& kind)
{
    std::ostringstream text;
    if (kind == "bool")
    {
        text << (read<bool>(cdr) ? 1 : 0);
    }
    else if (kind == "char")
    {
        text << static_cast<unsigned>(static_cast<unsigned char>(read<char>(cdr)));
    }
    else if (kind == "octet" || kind == "uint8")
    {
        text << static_cast<unsigned>(read<uint8_t>(cdr));
    }
    else if (kind == "int8")
    {
        text << static_cast<int>(read<int8_t>(cdr));
    }
    else if (kind == "int16")
    {
        text << read<int16_t>(cdr);
    }
    else if (kind == "uint16")
    {
        text << read<uint16_t>(cdr);
    }
    else if (kind == "int32")
    {
        text << read<int32_t>(cdr);
    }
    else if (kind == "uint32" || kind == "count")
    {
        text << read<uint32_t>(cdr);
    }
    else if (kind == "int64")
    {
        text << read<int64_t>(cdr);
    }
    else if (kind == "uint64")
    {
        text << read<uint64_t>(cdr);
    }
    else if (kind == "float32")
    {
        text << Float32Text::format(read<float>(cdr));
    }
    else if (kind == "float64")
    {
        text << Float64Text::format(read<double>(cdr));
    }
    else if (kind == "string")
    {
        std::string value = read<std::string>(cdr);
        text << hex_of(reinterpret_cast<const unsigned char*>(value.data()), value.size());
    }
    else if (kind == "wstring")
    {
        text << hex_of_wstring(read<std::wstring>(cdr));
    }
    else
    {
        throw BadInput("unknown op kind: " + kind);
    }
    return kind + " " + text.str();
}

const size_t kEncodeBufferSize = 4 << 20;

// One message's ops, up to the end of input or a line "---" (which ends
// each message of a batch); prints its hex line. Returns false at the end
// of input with no op read.
bool encode_one(
        std::istream& input,
        std::vector<char>& storage)
{
    // Fast-CDR skips padding bytes and leaves them as the buffer held them
    // (its own buffer grows with realloc: anything). A zeroed buffer of ours
    // makes them zero, as ROS 2's padding is meant to be, so whole images
    // compare; it does not grow, and an image beyond it is refused.
    std::fill(storage.begin(), storage.end(), 0);
    FastBuffer buffer(storage.data(), storage.size());
    Cdr cdr(buffer, Cdr::LITTLE_ENDIANNESS, Cdr::DDS_CDR);
    cdr.serialize_encapsulation();
    std::string line;
    bool ended = false;
    bool read_any = false;
    while (std::getline(input, line))
    {
        read_any = true;
        if (line == "---")
        {
            ended = true;
            break;
        }
        std::string kind;
        std::string value;
        split_op(line, kind, value);
        encode_op(cdr, kind, value);
    }
    if (!read_any)
    {
        return false;
    }
    std::cout << hex_of(reinterpret_cast<const unsigned char*>(buffer.getBuffer()),
            cdr.getSerializedDataLength()) << "\n";
    return ended;
}

int encode(
        std::istream& input)
{
    std::vector<char> storage(kEncodeBufferSize, 0);
    if (!encode_one(input, storage))
    {
        // No op at all: the empty message, the header alone.
        std::cout << "00010000\n";
        return 0;
    }
    while (encode_one(input, storage))
    {
    }
    return 0;
}

int decode(
        std::istream& input)
{
    std::string line;
    if (!std::getline(input, line))
    {
        throw BadInput("decode needs the buffer's hex on the first line");
    }
    std::vector<unsigned char> bytes = bytes_of_hex(line);
    // FastBuffer takes char*; an empty vector's data() may be null, which
    // Fast-CDR takes as a buffer of size 0 all the same.
    std::vector<char> data(bytes.begin(), bytes.end());
    FastBuffer buffer(data.data(), data.size());
    Cdr cdr(buffer, Cdr::LITTLE_ENDIANNESS, Cdr::DDS_CDR);
    cdr.read_encapsulation();
    while (std::getline(input, line))
    {
        std::string kind;
        std::string value;
        split_op(line, kind, value);
        std::cout << decode_op(cdr, kind) << "\n";
    }
    return 0;
}

} // namespace

int main(
        int argc,
        char** argv)
{
    std::string mode = argc == 2 ? argv[1] : "";
    if (mode != "encode" && mode != "decode")
    {
        std::cerr << "usage: " << argv[0] << " encode|decode < ops\n";
        return 2;
    }
    try
    {
        return mode == "encode" ? encode(std::cin) : decode(std::cin);
    }
    catch (const eprosima::fastcdr::exception::Exception& refusal)
    {
        std::cout << "error " << refusal.what() << std::endl;
        return 1;
    }
    catch (const BadInput& problem)
    {
        std::cout.flush();
        std::cerr << argv[0] << ": " << problem.what() << "\n";
        return 2;
    }
}
