// SPDX-License-Identifier: BSD-3-Clause
// A Fast DDS participant that moves already-serialized ROS 2 messages: the
// ROS 2 side of the tests (testing/dds_peer.py builds and runs it).
//
//   dds_raw_peer send|receive|echo --topic NAME --type TYPE_NAME
//                [--reply-topic NAME] [--reply-type TYPE_NAME]
//                [--reliability reliable|best-effort]
//                [--durability transient-local|volatile]
//                [--domain N] [--count N] [--timeout-ms N]
//
// A sample is a message's serialized bytes as they go into an RTPS DATA
// submessage: the 4-byte CDR encapsulation header (00 01 00 00 for little
// endian CDR) followed by the CDR body. The topic and type names are used as
// given, so the caller names them as ROS 2 does (rt/chatter,
// std_msgs::msg::dds_::String_); the type matches on its name only, as
// rmw_fastrtps' types do (no type object or type information is sent).
//
// send     reads one sample a line in hex from stdin (to EOF), waits until a
//          reader matched, writes each sample, waits until all are
//          acknowledged, prints "sent N" on stdout and exits 0.
// receive  prints each of --count samples (default 1) as one lowercase hex
//          line on stdout, nothing else, and exits 0.
// echo     as receive, and writes each sample as it came on --reply-topic
//          (of type --reply-type, default --type); once all --count are
//          written, waits until a reader of the reply matched and
//          acknowledged them, then exits 0.
// Each exits 1 with a line on stderr when --timeout-ms (default 10000)
// passes first, 2 on a usage error. "ready" goes to stderr once the
// participant and its endpoints exist; Fast DDS' own log goes to stderr too.
//
// The participant uses UDPv4 on 127.0.0.1 only (no shared memory, no other
// interface) and finds its peers there through the initial peers list; the
// domain is --domain, else ROS_DOMAIN_ID, else 0. Its endpoints keep the
// last 100 samples and are reliable and transient-local unless
// --reliability and --durability say otherwise: a reader that matches late
// still gets what was written. A reader only matches writers that offer as
// much (mros2's embeddedRTPS endpoints are best-effort and announce no
// durability, so volatile), and with a best-effort reader send's wait for
// acknowledgments returns at once.

#include <fastdds/dds/domain/DomainParticipant.hpp>
#include <fastdds/dds/domain/DomainParticipantFactory.hpp>
#include <fastdds/dds/domain/qos/DomainParticipantQos.hpp>
#include <fastdds/dds/log/Log.hpp>
#include <fastdds/dds/log/StdoutErrConsumer.hpp>
#include <fastdds/dds/publisher/DataWriter.hpp>
#include <fastdds/dds/publisher/Publisher.hpp>
#include <fastdds/dds/publisher/qos/DataWriterQos.hpp>
#include <fastdds/dds/subscriber/DataReader.hpp>
#include <fastdds/dds/subscriber/DataReaderListener.hpp>
#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <fastdds/dds/subscriber/Subscriber.hpp>
#include <fastdds/dds/subscriber/qos/DataReaderQos.hpp>
#include <fastdds/dds/topic/Topic.hpp>
#include <fastdds/dds/topic/TopicDataType.hpp>
#include <fastdds/dds/topic/TypeSupport.hpp>
#include <fastdds/rtps/transport/UDPv4TransportDescriptor.h>
#include <fastrtps/utils/IPLocator.h>

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <deque>
#include <iostream>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

using namespace eprosima::fastdds::dds;
using eprosima::fastrtps::rtps::SerializedPayload_t;
using eprosima::fastrtps::rtps::InstanceHandle_t;
using eprosima::fastrtps::rtps::Locator_t;
using eprosima::fastrtps::rtps::IPLocator;

namespace {

typedef std::vector<unsigned char> Bytes;

// The largest sample taken: a 64 KiB body and its encapsulation header.
const uint32_t MAX_SAMPLE = 64 * 1024 + 4;
const int KEPT_SAMPLES = 100;

// A type whose data is a sample's bytes, header included, under the name the
// caller gives.
class RawType : public TopicDataType
{
public:

    explicit RawType(
            const std::string& name)
    {
        setName(name.c_str());
        m_typeSize = MAX_SAMPLE;
        m_isGetKeyDefined = false;
        auto_fill_type_object(false);
        auto_fill_type_information(false);
    }

    bool serialize(
            void* data,
            SerializedPayload_t* payload) override
    {
        const Bytes& bytes = *static_cast<Bytes*>(data);
        if (bytes.size() < 4 || bytes.size() > payload->max_size)
        {
            return false;
        }
        std::memcpy(payload->data, bytes.data(), bytes.size());
        payload->length = static_cast<uint32_t>(bytes.size());
        // The representation identifier, big endian: 0x0001 is CDR_LE.
        payload->encapsulation = static_cast<uint16_t>((bytes[0] << 8) | bytes[1]);
        return true;
    }

    bool deserialize(
            SerializedPayload_t* payload,
            void* data) override
    {
        Bytes& bytes = *static_cast<Bytes*>(data);
        bytes.assign(payload->data, payload->data + payload->length);
        return true;
    }

    std::function<uint32_t()> getSerializedSizeProvider(
            void* data) override
    {
        const uint32_t size = static_cast<uint32_t>(static_cast<Bytes*>(data)->size());
        return [size]() -> uint32_t
               {
                   return size;
               };
    }

    void* createData() override
    {
        return new Bytes();
    }

    void deleteData(
            void* data) override
    {
        delete static_cast<Bytes*>(data);
    }

    bool getKey(
            void*,
            InstanceHandle_t*,
            bool) override
    {
        return false;
    }

    bool is_bounded() const override
    {
        return false;
    }

    bool is_plain() const override
    {
        return false;
    }

};

// Received samples, handed from Fast DDS' thread to the main one.
class Inbox : public DataReaderListener
{
public:

    void on_data_available(
            DataReader* reader) override
    {
        Bytes sample;
        SampleInfo info;
        while (reader->take_next_sample(&sample, &info) == ReturnCode_t::RETCODE_OK)
        {
            if (info.valid_data)
            {
                std::lock_guard<std::mutex> lock(mutex_);
                samples_.push_back(sample);
                changed_.notify_all();
            }
        }
    }

    // The next sample, or false when the deadline passes first.
    bool next(
            Bytes& sample,
            std::chrono::steady_clock::time_point deadline)
    {
        std::unique_lock<std::mutex> lock(mutex_);
        if (!changed_.wait_until(lock, deadline, [this]()
                {
                    return !samples_.empty();
                }))
        {
            return false;
        }
        sample = samples_.front();
        samples_.pop_front();
        return true;
    }

private:

    std::mutex mutex_;
    std::condition_variable changed_;
    std::deque<Bytes> samples_;
};

struct Options
{
    std::string mode;
    std::string topic;
    std::string type;
    std::string reply_topic;
    std::string reply_type;
    bool reliable = true;
    bool transient_local = true;
    uint32_t domain = 0;
    long count = 1;
    long timeout_ms = 10000;
};

void usage(
        const std::string& problem)
{
    std::cerr << "dds_raw_peer: " << problem << "\n"
              << "usage: dds_raw_peer send|receive|echo --topic NAME --type TYPE_NAME"
              << " [--reply-topic NAME] [--reply-type TYPE_NAME]"
              << " [--reliability reliable|best-effort] [--durability transient-local|volatile]"
              << " [--domain N] [--count N] [--timeout-ms N]" << std::endl;
    std::exit(2);
}

long number(
        const std::string& option,
        const std::string& text,
        long low,
        long high)
{
    char* end = nullptr;
    long value = std::strtol(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || value < low || value > high)
    {
        usage(option + " takes a number from " + std::to_string(low) + " to " + std::to_string(high)
                + ", not '" + text + "'");
    }
    return value;
}

Options parse(
        int argc,
        char** argv)
{
    Options options;
    const char* environment_domain = std::getenv("ROS_DOMAIN_ID");
    if (environment_domain != nullptr && *environment_domain != '\0')
    {
        options.domain = static_cast<uint32_t>(number("ROS_DOMAIN_ID", environment_domain, 0, 232));
    }
    if (argc < 2)
    {
        usage("no mode");
    }
    options.mode = argv[1];
    if (options.mode != "send" && options.mode != "receive" && options.mode != "echo")
    {
        usage("unknown mode '" + options.mode + "'");
    }
    for (int i = 2; i < argc; i += 2)
    {
        const std::string option = argv[i];
        if (i + 1 >= argc)
        {
            usage(option + " takes a value");
        }
        const std::string value = argv[i + 1];
        if (option == "--topic")
        {
            options.topic = value;
        }
        else if (option == "--type")
        {
            options.type = value;
        }
        else if (option == "--reply-topic")
        {
            options.reply_topic = value;
        }
        else if (option == "--reply-type")
        {
            options.reply_type = value;
        }
        else if (option == "--reliability" && (value == "reliable" || value == "best-effort"))
        {
            options.reliable = value == "reliable";
        }
        else if (option == "--durability" && (value == "transient-local" || value == "volatile"))
        {
            options.transient_local = value == "transient-local";
        }
        else if (option == "--domain")
        {
            options.domain = static_cast<uint32_t>(number(option, value, 0, 232));
        }
        else if (option == "--count")
        {
            options.count = number(option, value, 1, 1000000);
        }
        else if (option == "--timeout-ms")
        {
            options.timeout_ms = number(option, value, 1, 3600000);
        }
        else
        {
            usage("unknown option '" + option + "' or value '" + value + "'");
        }
    }
    if (options.topic.empty() || options.type.empty())
    {
        usage("--topic and --type are required");
    }
    if ((options.mode == "echo") == options.reply_topic.empty())
    {
        usage("echo takes --reply-topic, and only echo");
    }
    if (options.reply_type.empty())
    {
        options.reply_type = options.type;
    }
    return options;
}

int hex_digit(
        char c)
{
    if (c >= '0' && c <= '9')
    {
        return c - '0';
    }
    if (c >= 'a' && c <= 'f')
    {
        return c - 'a' + 10;
    }
    if (c >= 'A' && c <= 'F')
    {
        return c - 'A' + 10;
    }
    return -1;
}

// The samples on stdin, one a hex line; blank lines are skipped.
std::vector<Bytes> read_samples()
{
    std::vector<Bytes> samples;
    std::string line;
    size_t number = 0;
    while (std::getline(std::cin, line))
    {
        ++number;
        while (!line.empty() && (line.back() == '\r' || line.back() == ' '))
        {
            line.pop_back();
        }
        if (line.empty())
        {
            continue;
        }
        Bytes sample;
        bool good = line.size() % 2 == 0;
        for (size_t i = 0; good && i < line.size(); i += 2)
        {
            int high = hex_digit(line[i]);
            int low = hex_digit(line[i + 1]);
            good = high >= 0 && low >= 0;
            sample.push_back(static_cast<unsigned char>(high << 4 | low));
        }
        if (!good || sample.size() < 4 || sample.size() > MAX_SAMPLE)
        {
            usage("stdin line " + std::to_string(number)
                    + " is not a sample in hex (4 to " + std::to_string(MAX_SAMPLE) + " bytes)");
        }
        samples.push_back(sample);
    }
    return samples;
}

std::string hex(
        const Bytes& bytes)
{
    static const char digits[] = "0123456789abcdef";
    std::string text;
    text.reserve(bytes.size() * 2);
    for (unsigned char byte : bytes)
    {
        text += digits[byte >> 4];
        text += digits[byte & 0xf];
    }
    return text;
}

Locator_t loopback_locator()
{
    Locator_t locator;
    locator.kind = LOCATOR_KIND_UDPv4;
    IPLocator::setIPv4(locator, 127, 0, 0, 1);
    // Port 0: the well-known ports of the domain's first participants.
    locator.port = 0;
    return locator;
}

DomainParticipantQos participant_qos()
{
    DomainParticipantQos qos;
    qos.name("dds_raw_peer");
    qos.transport().use_builtin_transports = false;
    auto udp = std::make_shared<eprosima::fastdds::rtps::UDPv4TransportDescriptor>();
    udp->interfaceWhiteList.push_back("127.0.0.1");
    qos.transport().user_transports.push_back(udp);
    qos.wire_protocol().builtin.initialPeersList.push_back(loopback_locator());
    qos.wire_protocol().builtin.metatrafficUnicastLocatorList.push_back(loopback_locator());
    qos.wire_protocol().default_unicast_locator_list.push_back(loopback_locator());
    return qos;
}

template<typename Qos>
void endpoint_qos(
        Qos& qos,
        const Options& options)
{
    qos.reliability().kind = options.reliable ? RELIABLE_RELIABILITY_QOS : BEST_EFFORT_RELIABILITY_QOS;
    qos.durability().kind = options.transient_local ? TRANSIENT_LOCAL_DURABILITY_QOS
            : VOLATILE_DURABILITY_QOS;
    qos.history().kind = KEEP_LAST_HISTORY_QOS;
    qos.history().depth = KEPT_SAMPLES;
    qos.endpoint().history_memory_policy =
            eprosima::fastrtps::rtps::DYNAMIC_REUSABLE_MEMORY_MODE;
}

eprosima::fastrtps::Duration_t duration(
        long milliseconds)
{
    return eprosima::fastrtps::Duration_t(static_cast<int32_t>(milliseconds / 1000),
                   static_cast<uint32_t>(milliseconds % 1000) * 1000000u);
}

int fail(
        const std::string& message)
{
    std::cerr << "dds_raw_peer: " << message << std::endl;
    return 1;
}

std::string describe(
        const std::string& topic,
        const std::string& type)
{
    return topic + " (" + type + ")";
}

// The topic, its type registered under type_name if it is not yet.
Topic* make_topic(
        DomainParticipant* participant,
        const std::string& name,
        const std::string& type_name)
{
    if (!participant->find_type(type_name).empty()
            || TypeSupport(new RawType(type_name)).register_type(participant) == ReturnCode_t::RETCODE_OK)
    {
        return participant->create_topic(name, type_name, TOPIC_QOS_DEFAULT);
    }
    return nullptr;
}

DataWriter* make_writer(
        DomainParticipant* participant,
        Topic* topic,
        const Options& options)
{
    Publisher* publisher = participant->create_publisher(PUBLISHER_QOS_DEFAULT);
    DataWriterQos qos = DATAWRITER_QOS_DEFAULT;
    endpoint_qos(qos, options);
    return publisher == nullptr ? nullptr : publisher->create_datawriter(topic, qos);
}

DataReader* make_reader(
        DomainParticipant* participant,
        Topic* topic,
        DataReaderListener* listener,
        const Options& options)
{
    Subscriber* subscriber = participant->create_subscriber(SUBSCRIBER_QOS_DEFAULT);
    DataReaderQos qos = DATAREADER_QOS_DEFAULT;
    endpoint_qos(qos, options);
    return subscriber == nullptr ? nullptr : subscriber->create_datareader(topic, qos, listener);
}

long milliseconds_left(
        std::chrono::steady_clock::time_point deadline)
{
    long left = static_cast<long>(std::chrono::duration_cast<std::chrono::milliseconds>(
                deadline - std::chrono::steady_clock::now()).count());
    return left > 0 ? left : 0;
}

// 0 once a reader matched the writer, else 1 (with a line on stderr) at the
// deadline.
int wait_for_reader(
        DataWriter* writer,
        const std::string& what,
        const Options& options,
        std::chrono::steady_clock::time_point deadline)
{
    PublicationMatchedStatus matched;
    while (writer->get_publication_matched_status(matched) == ReturnCode_t::RETCODE_OK
            && matched.current_count == 0)
    {
        if (std::chrono::steady_clock::now() >= deadline)
        {
            return fail("no reader of " + what + " matched within " + std::to_string(options.timeout_ms)
                           + " ms");
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return 0;
}

int write(
        DataWriter* writer,
        const Bytes& sample)
{
    if (!writer->write(const_cast<Bytes*>(&sample)))
    {
        return fail("writing a sample of " + std::to_string(sample.size()) + " bytes failed");
    }
    return 0;
}

int wait_for_acknowledgments(
        DataWriter* writer,
        const std::string& what,
        const Options& options,
        std::chrono::steady_clock::time_point deadline)
{
    if (writer->wait_for_acknowledgments(duration(milliseconds_left(deadline))) != ReturnCode_t::RETCODE_OK)
    {
        return fail("the samples on " + what + " were not acknowledged within "
                       + std::to_string(options.timeout_ms) + " ms");
    }
    return 0;
}

int send(
        DataWriter* writer,
        const Options& options,
        std::chrono::steady_clock::time_point deadline)
{
    const std::string what = describe(options.topic, options.type);
    const std::vector<Bytes> samples = read_samples();
    int status = wait_for_reader(writer, what, options, deadline);
    for (size_t i = 0; status == 0 && i < samples.size(); ++i)
    {
        status = write(writer, samples[i]);
    }
    if (status == 0)
    {
        status = wait_for_acknowledgments(writer, what, options, deadline);
    }
    if (status == 0)
    {
        std::cout << "sent " << samples.size() << std::endl;
    }
    return status;
}

// receive, and echo when writer is not null.
int receive(
        Inbox& inbox,
        DataWriter* writer,
        const Options& options,
        std::chrono::steady_clock::time_point deadline)
{
    int status = 0;
    for (long received = 0; status == 0 && received < options.count; ++received)
    {
        Bytes sample;
        if (!inbox.next(sample, deadline))
        {
            return fail("received " + std::to_string(received) + " of " + std::to_string(options.count)
                           + " samples on " + describe(options.topic, options.type) + " within "
                           + std::to_string(options.timeout_ms) + " ms");
        }
        std::cout << hex(sample) << std::endl;
        if (writer != nullptr)
        {
            status = write(writer, sample);
        }
    }
    if (status == 0 && writer != nullptr)
    {
        const std::string what = describe(options.reply_topic, options.reply_type);
        status = wait_for_reader(writer, what, options, deadline);
        if (status == 0)
        {
            status = wait_for_acknowledgments(writer, what, options, deadline);
        }
    }
    return status;
}

} // namespace

int main(
        int argc,
        char** argv)
{
    const Options options = parse(argc, argv);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(options.timeout_ms);

    // Fast DDS' log on stderr, all of it: stdout carries the samples.
    Log::ClearConsumers();
    std::unique_ptr<StdoutErrConsumer> log(new StdoutErrConsumer());
    log->stderr_threshold(Log::Kind::Info);
    Log::RegisterConsumer(std::move(log));
    Log::SetVerbosity(Log::Kind::Warning);

    // Declared before the participant: it outlives the reader that calls it.
    Inbox inbox;
    DomainParticipantFactory* factory = DomainParticipantFactory::get_instance();
    DomainParticipant* participant = factory->create_participant(options.domain, participant_qos());
    if (participant == nullptr)
    {
        return fail("cannot create a participant in domain " + std::to_string(options.domain));
    }
    int status = 0;
    DataWriter* writer = nullptr;
    DataReader* reader = nullptr;
    Topic* topic = make_topic(participant, options.topic, options.type);
    if (topic == nullptr)
    {
        status = fail("cannot create topic " + describe(options.topic, options.type));
    }
    else if (options.mode == "send")
    {
        writer = make_writer(participant, topic, options);
        status = writer == nullptr ? fail("cannot create the writer") : 0;
    }
    else
    {
        reader = make_reader(participant, topic, &inbox, options);
        status = reader == nullptr ? fail("cannot create the reader") : 0;
        if (status == 0 && options.mode == "echo")
        {
            Topic* reply = make_topic(participant, options.reply_topic, options.reply_type);
            writer = reply == nullptr ? nullptr : make_writer(participant, reply, options);
            status = writer == nullptr
                    ? fail("cannot create the writer of " + describe(options.reply_topic, options.reply_type))
                    : 0;
        }
    }
    if (status == 0)
    {
        std::cerr << "ready" << std::endl;
        status = options.mode == "send" ? send(writer, options, deadline)
                : receive(inbox, writer, options, deadline);
    }
    if (reader != nullptr)
    {
        reader->set_listener(nullptr);
    }
    participant->delete_contained_entities();
    factory->delete_participant(participant);
    Log::Flush();
    return status;
}
