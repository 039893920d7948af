// SPDX-License-Identifier: MIT
// The bash and zsh completions of both programs (docgen.h): commands, options, the values
// of the options that take one of a few words, scene ids, file names, and after --set the
// parameter names of the scene on the line.
#include "docgen.h"

#include "command_table.h"
#include "help.h"

#include "../../core/scene.h"
#include "../window_options.h"

#include <ostream>
#include <sstream>

namespace ab::cli {

namespace {

enum class Kind { Free, Words, WordsOrFiles, Files, Params };

struct CompOption {
    std::string name;
    bool flag = false;
    bool repeatable = false;
    std::string value, help;
    Kind kind = Kind::Free;
    std::vector<std::string> words;
};

struct CompCommand {
    std::string name, summary;
    std::vector<CompOption> options;
    std::string operand;
    Kind operandKind = Kind::Free;
    std::vector<std::string> operandWords;
};

std::vector<std::string> split(const std::string& text, char sep)
{
    std::vector<std::string> parts;
    std::string part;
    std::istringstream in(text);
    while (std::getline(in, part, sep))
        if (!part.empty())
            parts.push_back(part);
    return parts;
}

// The lower-case alternatives of a placeholder ("report|physical", "WxH|720p|1080p").
std::vector<std::string> placeholderWords(const std::string& value)
{
    std::vector<std::string> words;
    if (value.find('|') == std::string::npos)
        return words;
    for (const std::string& w : split(value, '|'))
        if (w.find_first_of("ABCDEFGHIJKLMNOPQRSTUVWXYZ[]:") == std::string::npos)
            words.push_back(w);
    return words;
}

void classify(Values v, const std::string& value, Kind& kind, std::vector<std::string>& words)
{
    if (v == Values::File) {
        kind = Kind::Files;
        return;
    }
    if (v == Values::Assignment) {
        kind = Kind::Params;
        return;
    }
    words = v == Values::None ? placeholderWords(value) : valueWords(v);
    kind = words.empty() ? Kind::Free : v == Values::Preset ? Kind::WordsOrFiles : Kind::Words;
}

std::vector<CompCommand> cliCommands()
{
    std::vector<CompCommand> commands;
    for (const CommandSpec& c : commandTable()) {
        CompCommand cc{c.name, c.summary, {}, c.operand, Kind::Free, {}};
        classify(c.operandValues, "", cc.operandKind, cc.operandWords);
        for (const OptionSpec& o : c.options) {
            CompOption co{o.name, o.flag(), o.repeatable, o.value, o.help, Kind::Free, {}};
            classify(o.values, o.value, co.kind, co.words);
            cc.options.push_back(co);
        }
        commands.push_back(cc);
    }
    return commands;
}

CompCommand windowCommand()
{
    CompCommand cc{"amazeballs", "", {}, "FILE.json", Kind::Files, {}};
    for (const app::WindowOption& w : app::windowOptions()) {
        CompOption co{w.name, *w.value == '\0', std::string(w.name) == "set", w.value, w.help, Kind::Free, {}};
        classify(w.values, "", co.kind, co.words);
        if (*w.words) {
            co.words = split(w.words, ' ');
            co.kind = Kind::Words;
        }
        cc.options.push_back(co);
    }
    for (const auto& [flag, help] :
         {std::pair{"help", "print the options"}, std::pair{"help-all", "print the options, Qt's among them"},
          std::pair{"version", "print the program's name and version"}})
        cc.options.push_back({flag, true, false, "", help, Kind::Free, {}});
    return cc;
}

std::string spaced(const std::vector<std::string>& words)
{
    std::string text;
    for (const std::string& w : words)
        text += (text.empty() ? "" : " ") + w;
    return text;
}

// The parameter names of every scene, and of all scenes together (no scene on the line).
void paramNames(std::ostream& out, const std::string& indent, const std::string& assign)
{
    std::vector<std::string> all;
    for (const SceneInfo* s : allScenes()) {
        std::vector<std::string> names;
        for (const ParamSpec& p : s->params) {
            names.push_back(p.key);
            if (std::find(all.begin(), all.end(), p.key) == all.end())
                all.push_back(p.key);
        }
        out << indent << s->key << ") " << assign << spaced(names) << (assign.back() == '"' ? "\"" : ")") << " ;;\n";
    }
    out << indent << "*) " << assign << spaced(all) << (assign.back() == '"' ? "\"" : ")") << " ;;\n";
}

// ---- bash ----

void bashValueCase(std::ostream& out, const std::string& key, const CompOption& o)
{
    out << "    \"" << key << " --" << o.name << "\") ";
    switch (o.kind) {
    case Kind::Words:
        out << "COMPREPLY=($(compgen -W \"" << spaced(o.words) << "\" -- \"$cur\")) ;;\n";
        break;
    case Kind::WordsOrFiles:
        out << "compopt -o filenames 2>/dev/null; COMPREPLY=($(compgen -W \"" << spaced(o.words)
            << "\" -- \"$cur\") $(compgen -f -- \"$cur\")) ;;\n";
        break;
    case Kind::Files:
        out << "compopt -o filenames 2>/dev/null; COMPREPLY=($(compgen -f -- \"$cur\")) ;;\n";
        break;
    case Kind::Params:
        out << "compopt -o nospace 2>/dev/null; COMPREPLY=($(compgen -S = -W \"$("
            << "_amazeballs_params "
            << "\"$scene\")\" -- \"$cur\")) ;;\n";
        break;
    case Kind::Free:
        out << "COMPREPLY=() ;;\n";
        break;
    }
}

void bashParams(std::ostream& out)
{
    out << "# The parameter names --set takes in the scene $1 (every scene's without one).\n"
           "_amazeballs_params()\n{\n    case $1 in\n";
    std::ostringstream cases;
    paramNames(cases, "    ", "echo \"");
    out << cases.str() << "    esac\n}\n\n";
}

std::string bashScenes()
{
    return spaced(valueWords(Values::Scene));
}

// The part every program's function shares: the scene on the line, then the value of the
// option before the cursor, the options, or the operand.
void bashBody(std::ostream& out, const std::vector<CompCommand>& commands, const std::string& keyExpr,
              std::size_t firstWord)
{
    out << "    local scene=\"\" given=\"\" word\n"
           "    for word in \"${COMP_WORDS[@]:"
        << firstWord << ":COMP_CWORD-" << firstWord
        << "}\"; do\n"
           "        case \" "
        << bashScenes()
        << " \" in *\" $word \"*) scene=$word ;; esac\n"
           "        [[ -n $operand && \" $operand \" == *\" $word \"* ]] && given=$word\n"
           "    done\n"
           "    [[ $prev == = && COMP_CWORD -gt 1 ]] && prev=${COMP_WORDS[COMP_CWORD-2]}\n"
           "    case \""
        << keyExpr << " $prev\" in\n";
    for (const CompCommand& c : commands)
        for (const CompOption& o : c.options)
            if (!o.flag)
                bashValueCase(out, c.name, o);
    out << "    *)\n"
           "        if [[ $cur == -* || $files$operand == \"\" || -n $given ]]; then\n"
           "            COMPREPLY=($(compgen -W \"$options\" -- \"$cur\"))\n"
           "        elif [[ -n $files ]]; then\n"
           "            compopt -o filenames 2>/dev/null; COMPREPLY=($(compgen -f -- \"$cur\"))\n"
           "        else\n"
           "            COMPREPLY=($(compgen -W \"$operand\" -- \"$cur\"))\n"
           "        fi ;;\n"
           "    esac\n";
}

std::string optionWords(const CompCommand& c, bool help)
{
    std::string words;
    for (const CompOption& o : c.options)
        words += (words.empty() ? "--" : " --") + o.name;
    if (help)
        words += words.empty() ? "--help" : " --help";
    return words;
}

} // namespace

void writeCliBashCompletion(std::ostream& out)
{
    const std::vector<CompCommand> commands = cliCommands();
    out << "# bash completion for amazeballs-cli; generated from its command table, do not edit.\n\n";
    bashParams(out);
    out << "_amazeballs_cli()\n{\n"
           "    local cur=${COMP_WORDS[COMP_CWORD]} prev=${COMP_WORDS[COMP_CWORD-1]}\n"
           "    if ((COMP_CWORD == 1)); then\n"
           "        COMPREPLY=($(compgen -W \"";
    for (const CompCommand& c : commands)
        out << c.name << " ";
    out << "--help --version\" -- \"$cur\"))\n"
           "        return\n"
           "    fi\n"
           "    local options=\"\" operand=\"\" files=\"\"\n"
           "    case ${COMP_WORDS[1]} in\n";
    for (const CompCommand& c : commands)
        out << "    " << c.name << ") options=\"" << optionWords(c, true) << "\" operand=\"" << spaced(c.operandWords)
            << "\" ;;\n";
    out << "    *) return ;;\n    esac\n";
    bashBody(out, commands, "${COMP_WORDS[1]}", 2);
    out << "}\n\ncomplete -F _amazeballs_cli amazeballs-cli\n";
}

void writeWindowBashCompletion(std::ostream& out)
{
    const CompCommand c = windowCommand();
    out << "# bash completion for amazeballs; generated from its option table, do not edit.\n\n";
    bashParams(out);
    out << "_amazeballs()\n{\n"
           "    local cur=${COMP_WORDS[COMP_CWORD]} prev=${COMP_WORDS[COMP_CWORD-1]}\n"
           "    local options=\""
        << optionWords(c, false) << "\" operand=\"\" files=1\n";
    bashBody(out, {c}, "amazeballs", 1);
    out << "}\n\ncomplete -F _amazeballs amazeballs\n";
}

namespace {

// ---- zsh ----

// Text inside a single-quoted _arguments spec: quotes closed and reopened, and the
// characters that end the part it is in escaped (brackets in an explanation, colons in a
// message).
std::string zshText(const std::string& text, const char* special)
{
    std::string out;
    for (const char c : text) {
        if (c == '\'')
            out += "'\\''";
        else if (std::string_view(special).find(c) != std::string_view::npos || c == '\\')
            out += std::string("\\") + c;
        else
            out += c;
    }
    return out;
}

std::string zshExplanation(const std::string& text)
{
    return zshText(text, "[]");
}

std::string zshMessage(const std::string& text)
{
    return zshText(text, ":");
}

std::string zshAction(Kind kind, const std::vector<std::string>& words)
{
    const std::string list = spaced(words);
    switch (kind) {
    case Kind::Words:
        return std::string("(").append(list).append(")");
    case Kind::WordsOrFiles:
        return std::string("{compadd -- ").append(list).append("; _files}");
    case Kind::Files:
        return "_files";
    case Kind::Params:
        return "_amazeballs_zsh_params";
    case Kind::Free:
        break;
    }
    return " ";
}

void zshArguments(std::ostream& out, const CompCommand& c, const std::string& indent, bool help)
{
    out << indent << "_arguments -s -S";
    if (help)
        out << " \\\n" << indent << "  '(- *)'{-h,--help}'[print this usage]'";
    for (const CompOption& o : c.options) {
        out << " \\\n"
            << indent << "  '" << (o.repeatable ? "*" : "") << "--" << o.name << "[" << zshExplanation(o.help) << "]";
        if (!o.flag)
            out << ":" << zshMessage(o.value) << ":" << zshAction(o.kind, o.words);
        out << "'";
    }
    if (!c.operand.empty())
        out << " \\\n"
            << indent << "  '1:" << zshMessage(c.operand) << ":" << zshAction(c.operandKind, c.operandWords) << "'";
    out << "\n";
}

void zshParams(std::ostream& out)
{
    out << "# The parameter names --set takes in the scene on the line (every scene's without one).\n"
           "_amazeballs_zsh_params() {\n"
           "  local -a names\n"
           "  local scene=${${(M)words:#("
        <<
        [] {
            std::string alt;
            for (const std::string& s : valueWords(Values::Scene))
                alt += (alt.empty() ? "" : "|") + s;
            return alt;
        }()
        << ")}[1]}\n  case $scene in\n";
    paramNames(out, "    ", "names=(");
    out << "  esac\n  compadd -S = -- $names\n}\n\n";
}

void zshTail(std::ostream& out, const std::string& function, const std::string& program)
{
    out << "\nif [[ $funcstack[1] == " << function << " ]]; then\n  " << function << " \"$@\"\nelse\n  compdef "
        << function << " " << program << "\nfi\n";
}

} // namespace

void writeCliZshCompletion(std::ostream& out)
{
    out << "#compdef amazeballs-cli\n# zsh completion for amazeballs-cli; generated from its command table, do not "
           "edit.\n\n";
    zshParams(out);
    out << "_amazeballs-cli() {\n  local -a commands\n  commands=(\n";
    const std::vector<CompCommand> commands = cliCommands();
    for (const CompCommand& c : commands)
        out << "    '" << c.name << ":" << zshText(c.summary, "") << "'\n";
    out << "  )\n  if (( CURRENT == 2 )); then\n    _describe -t commands 'amazeballs-cli command' commands\n"
           "    compadd -- --help --version\n    return\n  fi\n"
           "  local command=$words[2]\n  shift words\n  (( CURRENT-- ))\n  case $command in\n";
    for (const CompCommand& c : commands) {
        out << "  " << c.name << ")\n";
        zshArguments(out, c, "    ", true);
        out << "    ;;\n";
    }
    out << "  esac\n}\n";
    zshTail(out, "_amazeballs-cli", "amazeballs-cli");
}

void writeWindowZshCompletion(std::ostream& out)
{
    out << "#compdef amazeballs\n# zsh completion for amazeballs; generated from its option table, do not edit.\n\n";
    zshParams(out);
    out << "_amazeballs() {\n";
    zshArguments(out, windowCommand(), "  ", false);
    out << "}\n";
    zshTail(out, "_amazeballs", "amazeballs");
}

} // namespace ab::cli
