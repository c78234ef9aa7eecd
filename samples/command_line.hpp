// This file is part of OpenCV project.
// It is subject to the license terms in the LICENSE file found in the top-level directory
// of this distribution and at http://opencv.org/license.html.

// The samples' command line and error reporting. OpenCV's CommandLineParser reads the options;
// what it would let through is answered here, before any work, with one "Error: ..." line and
// exit status 1: an unknown option, an option without its value, an extra argument, a missing
// required option, a number that is not one or lies outside its documented range, a word that
// is not one of the accepted ones. "--input building.jpg" and "-H H1to3p.xml" (a space instead
// of '=') mean "--input=building.jpg" and "--homography=H1to3p.xml", as for the Python samples.

#ifndef OPENCV_LSD_ADVANCE_SAMPLES_COMMAND_LINE_HPP
#define OPENCV_LSD_ADVANCE_SAMPLES_COMMAND_LINE_HPP

#include <opencv2/core.hpp>
#include <opencv2/core/utility.hpp>
#include <opencv2/core/utils/filesystem.hpp>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <limits>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

//! OpenCV's file parsers (FileStorage) throw their own name as the message and
//! "<file>(<line>): <reason>" as the function: for such an exception, message becomes
//! "cannot parse <file>: line <line>: <reason>" and the result is true.
inline bool parseErrorMessage(const cv::Exception& e, std::string& message)
{
    for (const std::string& text : { e.func, e.err })
    {
        const size_t open = text.rfind('('), close = text.find("): ", open == std::string::npos ? 0 : open);
        if (e.code != cv::Error::StsParseError || open == std::string::npos || close == std::string::npos ||
            close <= open + 1 || text.find_first_not_of("0123456789", open + 1) != close)
            continue;
        message = "cannot parse " + text.substr(0, open) + ": line " + text.substr(open + 1, close - open - 1) + ": " +
                  text.substr(close + 3);
        return true;
    }
    return false;
}

//! A cv::Exception as one line for a person.
inline std::string messageOf(const cv::Exception& e)
{
    std::string message;
    return parseErrorMessage(e, message) ? message : e.err;
}

//! Runs a sample's main work; an exception becomes "Error: <message>" on stderr and exit code 1.
inline int runReportingErrors(const std::function<int()>& run)
{
    try
    {
        return run();
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

//! Throws unless the folder of the output file of --option=path exists (an empty path is
//! fine), so that a run does not fail at its end.
inline void checkOutputFolder(const std::string& option, const std::string& path)
{
    const size_t slash = path.find_last_of('/');
    const std::string folder = slash == std::string::npos ? std::string(".") : path.substr(0, std::max<size_t>(slash, 1));
    if (!path.empty() && !cv::utils::fs::isDirectory(folder))
        throw std::runtime_error("--" + option + "=" + path + ": the folder " + folder + " does not exist");
}

//! Upper bound of CommandLine::number() for a number without one.
constexpr double kUnbounded = std::numeric_limits<double>::max();

//! The options of a sample: CommandLineParser's keys, checked as described at the top.
class CommandLine
{
public:
    /** @param keys CommandLineParser's keys ("{name alias | default | help}"; default <none>:
    required; @name: positional).
    @param flags Options that take no value (help is one already).
    @param optionalValues Options that may stand alone (then they read "true"); given a value,
    with '=' or as the next argument when that is not an option. */
    CommandLine(int argc, const char* const argv[], const cv::String& keys, const cv::String& about,
                const std::set<std::string>& flags, const std::set<std::string>& optionalValues = {})
        : options_(optionsOf(keys)), arguments_(normalised(argc, argv, flags, optionalValues)),
          argumentPointers_(pointersTo(arguments_)),
          parser_((int)argumentPointers_.size(), argumentPointers_.data(), keys)
    {
        parser_.about(about);
        if (helpAsked())
            return;
        size_t positional = 0;
        for (const Option& o : options_)
        {
            // Positionals are given in order; CommandLineParser's has() is true for a <none> default.
            const bool given = o.names[0][0] == '@' ? positional++ < positionalsGiven_ : given_.count(o.names[0]) > 0;
            if (o.required && !given)
                throw std::runtime_error((o.names[0][0] == '@' ? o.names[0].substr(1) : "--" + o.names[0]) +
                                         " is required: " + o.help);
        }
    }

    //! --help or -h was given: print the help and exit 0, whatever else the command line holds.
    bool helpAsked() const { return parser_.has("help"); }
    void printHelp() const { parser_.printMessage(); }

    //! The option was given (a flag, or a value option with a value).
    bool has(const std::string& name) const { return parser_.has(name); }

    //! The option's value as given, or its default.
    std::string text(const std::string& name) const { return parser_.get<cv::String>(name); }

    //! The option's value, which must be one of choices.
    std::string oneOf(const std::string& name, const std::vector<std::string>& choices) const
    {
        const std::string value = text(name);
        for (const std::string& c : choices)
            if (value == c)
                return value;
        std::string list;
        for (size_t i = 0; i < choices.size(); i++)
            list += (i == 0 ? "" : i + 1 == choices.size() ? " or " : ", ") + choices[i];
        throw std::runtime_error("--" + name + " must be " + list + ", got '" + value + "'");
    }

    //! The option's value as an integer in [low, high].
    int integer(const std::string& name, int low, int high = std::numeric_limits<int>::max()) const
    {
        const std::string value = text(name);
        char* end = nullptr;
        errno = 0;
        const long v = std::strtol(value.c_str(), &end, 10);
        if (value.empty() || *end != '\0' || errno == ERANGE || v < low || v > high)
            throw std::runtime_error("--" + name + " must be an integer " + rangeText(low, high, false) + ", got '" +
                                     value + "'");
        return (int)v;
    }

    //! The option's value as a finite number in [low, high], or (low, high] with lowExcluded.
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
        bool required = false;
        std::string help;
    };

    static std::string trimmed(const std::string& s)
    {
        const size_t first = s.find_first_not_of(" \t"), last = s.find_last_not_of(" \t");
        return first == std::string::npos ? std::string() : s.substr(first, last - first + 1);
    }

    static std::vector<Option> optionsOf(const std::string& keys)
    {
        std::vector<Option> options;
        for (size_t open = keys.find('{'); open != std::string::npos; open = keys.find('{', open + 1))
        {
            const size_t close = keys.find('}', open);
            CV_Assert(close != std::string::npos);
            std::vector<std::string> fields;
            std::stringstream entry(keys.substr(open + 1, close - open - 1));
            for (std::string field; std::getline(entry, field, '|');)
                fields.push_back(trimmed(field));
            CV_Assert(fields.size() == 3);
            Option o;
            std::stringstream names(fields[0]);
            for (std::string name; names >> name;)
                o.names.push_back(name);
            o.required = fields[1] == "<none>";
            o.help = fields[2];
            options.push_back(o);
        }
        return options;
    }

    //! The option named name (or alias), null when there is none.
    const Option* find(const std::string& name) const
    {
        for (const Option& o : options_)
            for (const std::string& n : o.names)
                if (n == name && name[0] != '@')
                    return &o;
        return nullptr;
    }

    static bool isNumber(const std::string& s)
    {
        char* end = nullptr;
        std::strtod(s.c_str(), &end);
        return !s.empty() && *end == '\0';
    }

    static std::string rangeText(double low, double high, bool lowExcluded)
    {
        const bool unbounded = high >= std::numeric_limits<int>::max();
        if (unbounded)
            return cv::format(lowExcluded ? "> %g" : ">= %g", low);
        return cv::format(lowExcluded ? "in (%g, %g]" : "in [%g, %g]", low, high);
    }

    // The arguments with every option as --name=value under its first name, so that
    // CommandLineParser reads "--input building.jpg" as the user meant it; only --help when
    // help is asked for.
    std::vector<std::string> normalised(int argc, const char* const argv[], const std::set<std::string>& flags,
                                        const std::set<std::string>& optionalValues)
    {
        std::vector<std::string> out(1, argc > 0 ? argv[0] : "");
        for (int i = 1; i < argc; i++)
            for (const char* help : { "-h", "--h", "-help", "--help" })
                if (std::string(argv[i]) == help)
                    return { out[0], "--help" };
        size_t positionalsAccepted = 0;
        for (const Option& o : options_)
            positionalsAccepted += o.names[0][0] == '@';
        for (int i = 1; i < argc; i++)
        {
            const std::string arg = argv[i];
            if (arg.size() < 2 || arg[0] != '-' || isNumber(arg))
            {
                if (++positionalsGiven_ > positionalsAccepted)
                    throw std::runtime_error("unexpected argument '" + arg + "' (options are written --name=value; "
                                             "--help lists them)");
                out.push_back(arg);
                continue;
            }
            const std::string body = arg.substr(arg[1] == '-' ? 2 : 1);
            const size_t equals = body.find('=');
            const std::string name = body.substr(0, equals);
            const Option* option = find(name);
            if (!option)
                throw std::runtime_error("unknown option " + arg.substr(0, arg.find('=')) + "; --help lists the options");
            const std::string& canonical = option->names[0];
            given_.insert(canonical);
            const bool flag = canonical == "help" || flags.count(canonical) > 0;
            if (flag || equals != std::string::npos)
            {
                out.push_back("--" + canonical + (equals == std::string::npos ? "" : body.substr(equals)));
                continue;
            }
            const bool valueFollows = i + 1 < argc && (argv[i + 1][0] != '-' || isNumber(argv[i + 1]));
            if (valueFollows)
                out.push_back("--" + canonical + "=" + argv[++i]);
            else if (optionalValues.count(canonical))
                out.push_back("--" + canonical);
            else
                throw std::runtime_error("--" + canonical + " needs a value: --" + canonical + "=<value> (" +
                                         option->help + ")");
        }
        return out;
    }

    static std::vector<const char*> pointersTo(const std::vector<std::string>& strings)
    {
        std::vector<const char*> pointers;
        for (const std::string& s : strings)
            pointers.push_back(s.c_str());
        return pointers;
    }

    std::vector<Option> options_;
    std::set<std::string> given_;  //!< options on the command line, by their first name
    size_t positionalsGiven_ = 0;
    std::vector<std::string> arguments_;
    std::vector<const char*> argumentPointers_;
    cv::CommandLineParser parser_;
};

//! A sample's main(): its command line (CommandLine's arguments), --help printed with exit
//! status 0, else run(arguments); errors reported as by runReportingErrors.
inline int runSample(int argc, const char* const argv[], const cv::String& keys, const cv::String& about,
                     const std::set<std::string>& flags, const std::set<std::string>& optionalValues,
                     const std::function<int(const CommandLine&)>& run)
{
    return runReportingErrors([&] {
        const CommandLine args(argc, argv, keys, about, flags, optionalValues);
        if (args.helpAsked())
        {
            args.printHelp();
            return 0;
        }
        return run(args);
    });
}

#endif
