// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// What the apps promise their user. OpenCV's CommandLineParser reads the options; what it would
// let through (an unknown option, an option without its value, an extra argument, a missing
// required option, a number that is none or lies outside its range, a word that is not one of
// the accepted ones) is answered before any work with one "Error: ..." line and exit status 1.
// `--help` prints the options with their ranges and exits 0. A folder run reports each file
// that is not a readable image, goes on, and ends with exit status 2.

#ifndef OPENCV_LSD_ADVANCE_APPS_COMMAND_LINE_HPP
#define OPENCV_LSD_ADVANCE_APPS_COMMAND_LINE_HPP

#include <opencv2/core.hpp>
#include <opencv2/core/utility.hpp>
#include <opencv2/core/utils/filesystem.hpp>
#include <opencv2/imgcodecs.hpp>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iostream>
#include <iterator>
#include <limits>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

//! Exit status of a run that left out unreadable image files and did the others.
constexpr int kExitSkipped = 2;

//! The upper bound of AppOptions::number() for a number without one.
constexpr double kUnbounded = std::numeric_limits<int>::max();

//! The gray image of a file, empty when OpenCV cannot decode it. The bytes go to imdecode:
//! imread would also print libjpeg's warnings about a truncated JPEG, which the apps report.
inline cv::Mat readGrayImage(const std::string& path)
{
    std::ifstream file(path.c_str(), std::ios::binary);
    const std::vector<uchar> bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    return bytes.empty() ? cv::Mat() : cv::imdecode(bytes, cv::IMREAD_GRAYSCALE);
}

inline void reportSkipped(const std::string& path)
{
    std::cerr << "skipped " << path << ": not an image OpenCV can read" << std::endl;
}

//! A cv::Exception as one line for a person. OpenCV's file parsers (FileStorage) throw with
//! "<file>(<line>): <reason>" as the function (or, in some versions, as the message).
inline std::string messageOf(const cv::Exception& e)
{
    for (const std::string& text : { e.func, e.err })
    {
        const size_t open = text.rfind('('), close = text.find("): ", open == std::string::npos ? 0 : open);
        if (e.code == cv::Error::StsParseError && open != std::string::npos && close != std::string::npos &&
            close > open + 1 && text.find_first_not_of("0123456789", open + 1) == close)
            return "cannot parse " + text.substr(0, open) + ": line " + text.substr(open + 1, close - open - 1) + ": " +
                   text.substr(close + 3);
    }
    return e.err;
}

//! Throws unless the folder of the file that --option names exists (an empty path is fine),
//! so that a run does not fail at its end.
inline void checkOutputFolder(const std::string& option, const std::string& path)
{
    const size_t slash = path.find_last_of('/');
    const std::string folder = slash == std::string::npos ? std::string(".") : path.substr(0, std::max<size_t>(slash, 1));
    if (!path.empty() && !cv::utils::fs::isDirectory(folder))
        throw std::runtime_error("--" + option + "=" + path + ": the folder " + folder + " does not exist");
}

//! The LSDAdvance parameters file of --params, open for reading; closed for an empty path.
inline cv::FileStorage openParamsFile(const std::string& path)
{
    cv::FileStorage file;
    if (path.empty())
        return file;
    const std::string accepted = " (YAML, XML or JSON written by LSDAdvance::save() or write())";
    // Checked here: FileStorage would log an error of its own before failing.
    if (!cv::utils::fs::exists(path) || cv::utils::fs::isDirectory(path))
        throw std::runtime_error("no such parameters file: " + path + accepted);
    if (std::ifstream(path.c_str()).peek() == std::ifstream::traits_type::eof())
        throw std::runtime_error("the parameters file " + path + " is empty" + accepted);
    try
    {
        if (file.open(path, cv::FileStorage::READ))
            return file;
    }
    catch (const cv::Exception& e)
    {
        const std::string message = messageOf(e);
        throw std::runtime_error(message != e.err ? message : "cannot read the parameters file " + path + ": " + e.err + accepted);
    }
    throw std::runtime_error("cannot read the parameters file " + path + accepted);
}

//! An app's options: CommandLineParser's keys, checked as said at the top of this file.
class AppOptions
{
public:
    /** @param keys CommandLineParser's keys ("{name alias | default | help}"; default <none>:
    required; @name: positional).
    @param flags Options that take no value (help is one). Every other option is written
    --name=value. */
    AppOptions(int argc, const char* const argv[], const cv::String& keys, const cv::String& about,
               const std::set<std::string>& flags)
        : parser_(argc, argv, keys)
    {
        parser_.about(about);
        for (int i = 1; i < argc; i++)
            for (const char* help : { "-h", "--h", "-help", "--help" })
                help_ = help_ || std::string(argv[i]) == help;
        if (help_)
            return;
        std::set<std::string> given;
        size_t positionals = 0;
        const std::vector<Option> options = optionsOf(keys);
        for (int i = 1; i < argc; i++)
        {
            const std::string arg = argv[i];
            if (arg.size() < 2 || arg[0] != '-' || isNumber(arg))
            {
                if (++positionals > countPositionals(options))
                    throw std::runtime_error("unexpected argument '" + arg +
                                             "' (options are written --name=value; --help lists them)");
                continue;
            }
            const std::string name = arg.substr(arg[1] == '-' ? 2 : 1, arg.find('=') - (arg[1] == '-' ? 2 : 1));
            const Option* option = find(options, name);
            if (!option)
                throw std::runtime_error("unknown option " + arg.substr(0, arg.find('=')) + "; --help lists the options");
            if (!flags.count(option->names[0]) && arg.find('=') == std::string::npos)
                throw std::runtime_error("--" + option->names[0] + " needs a value: --" + option->names[0] +
                                         "=<value> (" + option->help + ")");
            given.insert(option->names[0]);
        }
        size_t positional = 0;
        for (const Option& o : options)
        {
            const bool isPositional = o.names[0][0] == '@';
            if (o.required && !(isPositional ? positional++ < positionals : given.count(o.names[0]) > 0))
                throw std::runtime_error((isPositional ? o.names[0].substr(1) : "--" + o.names[0]) + " is required: " +
                                         o.help);
        }
    }

    bool helpAsked() const { return help_; }
    void printHelp() const { parser_.printMessage(); }

    //! A flag was given, or a value option has a value (given or by default).
    bool has(const std::string& name) const { return parser_.has(name); }

    std::string text(const std::string& name) const { return parser_.get<cv::String>(name); }

    //! The option's value, which must be one of choices.
    std::string oneOf(const std::string& name, const std::vector<std::string>& choices) const
    {
        const std::string value = text(name);
        std::string list;
        for (size_t i = 0; i < choices.size(); i++)
        {
            if (value == choices[i])
                return value;
            list += (i == 0 ? "" : i + 1 == choices.size() ? " or " : ", ") + choices[i];
        }
        throw std::runtime_error("--" + name + " must be " + list + ", got '" + value + "'");
    }

    int integer(const std::string& name, int low, int high = std::numeric_limits<int>::max()) const
    {
        return integerOf(name, text(name), low, high);
    }

    //! A comma-separated list of at least one integer in [low, high].
    std::vector<int> integers(const std::string& name, int low) const
    {
        std::vector<int> values;
        std::stringstream list(text(name));
        for (std::string item; std::getline(list, item, ',');)
            values.push_back(integerOf(name, item, low, std::numeric_limits<int>::max()));
        if (values.empty())
            throw std::runtime_error("--" + name + " must be integers " + rangeText(low, kUnbounded, false) +
                                     " separated by commas, got ''");
        return values;
    }

    //! A finite number in [low, high], or in (low, high] with lowExcluded.
    double number(const std::string& name, double low, double high = kUnbounded, bool lowExcluded = false) const
    {
        const std::string value = text(name);
        char* end = nullptr;
        const double v = std::strtod(value.c_str(), &end);
        if (value.empty() || *end != '\0' || !std::isfinite(v) || v < low || (lowExcluded && v == low) || v > high)
            throw std::runtime_error("--" + name + " must be a number " + rangeText(low, high, lowExcluded) + ", got '" +
                                     value + "'");
        return v;
    }

private:
    struct Option
    {
        std::vector<std::string> names;  //!< the name, then its aliases; "@name" for a positional
        bool required;
        std::string help;
    };

    // The keys' entries: "{names | default | help}".
    static std::vector<Option> optionsOf(const std::string& keys)
    {
        std::vector<Option> options;
        for (size_t open = keys.find('{'); open != std::string::npos; open = keys.find('{', open + 1))
        {
            std::vector<std::string> fields;
            std::stringstream entry(keys.substr(open + 1, keys.find('}', open) - open - 1));
            for (std::string field; std::getline(entry, field, '|');)
                fields.push_back(field);
            CV_Assert(fields.size() == 3);
            Option o;
            std::stringstream names(fields[0]);
            for (std::string name; names >> name;)
                o.names.push_back(name);
            o.required = fields[1].find("<none>") != std::string::npos;
            o.help = fields[2].substr(1, fields[2].size() - 2);
            options.push_back(o);
        }
        return options;
    }

    static const Option* find(const std::vector<Option>& options, const std::string& name)
    {
        for (const Option& o : options)
            for (const std::string& n : o.names)
                if (n == name && n[0] != '@')
                    return &o;
        return nullptr;
    }

    static size_t countPositionals(const std::vector<Option>& options)
    {
        size_t n = 0;
        for (const Option& o : options)
            n += o.names[0][0] == '@';
        return n;
    }

    static bool isNumber(const std::string& s)
    {
        char* end = nullptr;
        std::strtod(s.c_str(), &end);
        return *end == '\0';
    }

    static int integerOf(const std::string& name, const std::string& value, int low, int high)
    {
        char* end = nullptr;
        errno = 0;
        const long v = std::strtol(value.c_str(), &end, 10);
        if (value.empty() || *end != '\0' || errno == ERANGE || v < low || v > high)
            throw std::runtime_error("--" + name + " must be an integer " + rangeText(low, high, false) + ", got '" +
                                     value + "'");
        return (int)v;
    }

    static std::string rangeText(double low, double high, bool lowExcluded)
    {
        if (high >= kUnbounded)
            return cv::format(lowExcluded ? "> %g" : ">= %g", low);
        return cv::format(lowExcluded ? "in (%g, %g]" : "in [%g, %g]", low, high);
    }

    cv::CommandLineParser parser_;
    bool help_ = false;
};

//! An app's main(): --help printed with exit status 0, else run(options); an exception becomes
//! "Error: <message>" on stderr and exit status 1.
inline int runApp(int argc, const char* const argv[], const cv::String& keys, const cv::String& about,
                  const std::set<std::string>& flags, const std::function<int(const AppOptions&)>& run)
{
    try
    {
        const AppOptions options(argc, argv, keys, about, flags);
        if (!options.helpAsked())
            return run(options);
        options.printHelp();
        return 0;
    }
    catch (const cv::Exception& e)
    {
        std::cerr << "Error: " << messageOf(e) << std::endl;
    }
    catch (const std::exception& e)
    {
        std::cerr << "Error: " << e.what() << std::endl;
    }
    return 1;
}

#endif
