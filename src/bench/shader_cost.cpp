#include "bench/shader_cost.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <map>
#include <set>
#include <sstream>
#include <vector>

namespace puddle::bench {

namespace {

// Whether `#if` / `#elif` `expression` holds: only `defined(X)` and `!defined(X)`; anything else passes.
bool condition_holds(const std::string& expression, const std::set<std::string>& defined) {
    const bool negated = expression.starts_with("!");
    const auto open = expression.find('('), close = expression.find(')');
    if (open == std::string::npos || close == std::string::npos) return true;
    return defined.contains(expression.substr(open + 1, close - open - 1)) != negated;
}

// Keeps the lines that the #ifdef/#ifndef/#if defined/#elif defined/#else/#endif around them let through,
// with the macros #define'd so far; drops every directive and comment.
std::string preprocess(std::string_view source) {
    std::string text;  // comments out first
    for (std::size_t i = 0; i < source.size(); ++i) {
        if (source.compare(i, 2, "//") == 0) {
            while (i < source.size() && source[i] != '\n') ++i;
            text += '\n';
        } else if (source.compare(i, 2, "/*") == 0) {
            const auto end = source.find("*/", i + 2);
            i = end == std::string_view::npos ? source.size() : end + 1;
            text += ' ';
        } else {
            text += source[i];
        }
    }
    std::set<std::string> defined;
    std::vector<bool> live{true};   // one entry per open #if; the last says whether lines pass
    std::vector<bool> taken{true};  // whether a branch of that #if has passed (an #elif or #else then cannot)
    std::istringstream in(text);
    std::string line, out;
    while (std::getline(in, line)) {
        const auto first = line.find_first_not_of(" \t");
        if (first == std::string::npos || line[first] != '#') {
            if (live.back()) out += line + '\n';
            continue;
        }
        std::istringstream words(line.substr(first + 1));
        std::string directive, name;
        words >> directive >> name;
        const bool outer = live.size() < 2 || live[live.size() - 2];
        if (directive == "define" && live.back()) {
            defined.insert(name);
        } else if (directive == "ifdef" || directive == "ifndef" || directive == "if") {
            const bool on = directive == "if" ? condition_holds(name, defined)
                                              : defined.contains(name) == (directive == "ifdef");
            live.push_back(live.back() && on);
            taken.push_back(on);
        } else if (directive == "elif" && live.size() > 1) {
            const bool on = !taken.back() && condition_holds(name, defined);
            live.back() = outer && on;
            taken.back() = taken.back() || on;
        } else if (directive == "else" && live.size() > 1) {
            live.back() = outer && !taken.back();
            taken.back() = true;
        } else if (directive == "endif" && live.size() > 1) {
            live.pop_back();
            taken.pop_back();
        }
    }
    return out;
}

std::vector<std::string> tokenize(const std::string& text) {
    static const std::vector<std::string> pairs{
        "+=", "-=", "*=", "/=", "<=", ">=", "==", "!=", "&&", "||", "++", "--"};
    std::vector<std::string> tokens;
    for (std::size_t i = 0; i < text.size();) {
        const char c = text[i];
        if (std::isspace(static_cast<unsigned char>(c))) {
            ++i;
        } else if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
            std::size_t j = i;
            while (j < text.size() && (std::isalnum(static_cast<unsigned char>(text[j])) || text[j] == '_'))
                ++j;
            tokens.push_back(text.substr(i, j - i));
            i = j;
        } else if (std::isdigit(static_cast<unsigned char>(c)) ||
                   (c == '.' && i + 1 < text.size() &&
                    std::isdigit(static_cast<unsigned char>(text[i + 1])))) {
            std::size_t j = i;
            while (j < text.size() &&
                   (std::isalnum(static_cast<unsigned char>(text[j])) || text[j] == '.' ||
                    ((text[j] == '-' || text[j] == '+') && (text[j - 1] == 'e' || text[j - 1] == 'E'))))
                ++j;
            tokens.push_back(text.substr(i, j - i));
            i = j;
        } else {
            const auto pair = std::find_if(pairs.begin(), pairs.end(),
                                           [&](const std::string& p) { return text.compare(i, 2, p) == 0; });
            tokens.push_back(pair != pairs.end() ? *pair : std::string(1, c));
            i += tokens.back().size();
        }
    }
    return tokens;
}

// ALU weight of a built-in function; absent names (constructors, user functions) weigh nothing here.
int builtin_weight(const std::string& name) {
    static const std::map<std::string, int> weights{
        {"abs", 1},      {"sign", 1},       {"floor", 1},     {"ceil", 1},        {"fract", 1},
        {"min", 1},      {"max", 1},        {"clamp", 2},     {"step", 1},        {"mod", 2},
        {"mix", 2},      {"dot", 1},        {"sqrt", 1},      {"inversesqrt", 1}, {"exp", 2},
        {"exp2", 1},     {"log", 2},        {"log2", 1},      {"pow", 3},         {"sin", 1},
        {"cos", 1},      {"tan", 2},        {"atan", 4},      {"asin", 4},        {"acos", 4},
        {"length", 2},   {"distance", 3},   {"normalize", 3}, {"cross", 2},       {"reflect", 3},
        {"refract", 6},  {"smoothstep", 4}, {"any", 1},       {"all", 1},         {"greaterThan", 1},
        {"lessThan", 1}, {"equal", 1},      {"notEqual", 1},  {"dFdx", 1},        {"dFdy", 1},
        {"fwidth", 2},
    };
    const auto it = weights.find(name);
    return it == weights.end() ? 0 : it->second;
}

bool is_fetch(const std::string& name) {
    return name == "texture" || name == "textureLod" || name == "texelFetch" || name == "textureGrad" ||
           name == "textureOffset" || name == "textureProj" || name == "textureLodOffset" ||
           name == "texelFetchOffset";
}

bool is_op(const std::string& t) {
    static const std::set<std::string> ops{"+", "-",  "*",  "/",  "+=", "-=", "*=", "/=", "<",
                                           ">", "<=", ">=", "==", "!=", "&&", "||", "?",  "!"};
    return ops.contains(t);
}

class Estimator {
public:
    Estimator(std::vector<std::string> tokens, int max_loop) : t_(std::move(tokens)), max_loop_(max_loop) {
        for (std::size_t i = 0, depth = 0; i < t_.size(); ++i) {  // function definitions at file scope
            if (t_[i] == "{") ++depth;
            if (t_[i] == "}") --depth;
            if (depth == 0 && i + 1 < t_.size() && t_[i + 1] == "(" && is_name(t_[i])) {
                const std::size_t close = match(i + 1);
                if (close + 1 < t_.size() && t_[close + 1] == "{") {
                    bodies_[t_[i]] = {close + 2, match(close + 1)};
                    i = match(close + 1);
                }
            }
        }
    }

    ShaderCost function(const std::string& name) {
        if (const auto done = memo_.find(name); done != memo_.end()) return done->second;
        const auto body = bodies_.find(name);
        if (body == bodies_.end() || in_progress_.contains(name)) return {};
        in_progress_.insert(name);
        const ShaderCost c = range(body->second.first, body->second.second);
        in_progress_.erase(name);
        return memo_[name] = c;
    }

private:
    static bool is_name(const std::string& s) {
        return !s.empty() && (std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_');
    }

    // The index of the bracket closing the one at `open`.
    std::size_t match(std::size_t open) const {
        const std::string& o = t_[open];
        const std::string c = o == "(" ? ")" : o == "{" ? "}" : "]";
        int depth = 0;
        for (std::size_t i = open; i < t_.size(); ++i) {
            if (t_[i] == o) ++depth;
            if (t_[i] == c && --depth == 0) return i;
        }
        return t_.size() - 1;
    }

    // The trip count of a loop header `( ... i < N ... )`, capped; the cap when it is not a literal.
    int trips(std::size_t open, std::size_t close) const {
        for (std::size_t i = open; i + 1 < close; ++i) {
            if (t_[i] != "<" && t_[i] != "<=") continue;
            int n = 0;
            const std::string& s = t_[i + 1];
            if (std::from_chars(s.data(), s.data() + s.size(), n).ec == std::errc())
                return std::min(t_[i] == "<=" ? n + 1 : n, max_loop_);
        }
        return max_loop_;
    }

    ShaderCost range(std::size_t begin, std::size_t end) {
        ShaderCost c;
        auto add = [&c](ShaderCost x, int times) {
            c.texture_fetches += x.texture_fetches * times;
            c.alu_ops += x.alu_ops * times;
        };
        for (std::size_t i = begin; i < end; ++i) {
            const std::string& tok = t_[i];
            if ((tok == "for" || tok == "while") && i + 1 < end && t_[i + 1] == "(") {
                const std::size_t header_end = match(i + 1);
                const int n = tok == "for" ? trips(i + 1, header_end) : max_loop_;
                std::size_t body_end = header_end + 1;
                if (body_end < end && t_[body_end] == "{") {
                    body_end = match(body_end);
                    add(range(header_end + 2, body_end), n);
                } else {
                    while (body_end < end && t_[body_end] != ";") ++body_end;
                    add(range(header_end + 1, body_end), n);
                }
                i = body_end;
            } else if (is_name(tok) && i + 1 < end && t_[i + 1] == "(") {
                if (is_fetch(tok)) ++c.texture_fetches;
                c.alu_ops += builtin_weight(tok);
                if (tok != "if") add(function(tok), 1);
            } else if (is_op(tok)) {
                ++c.alu_ops;
            }
        }
        return c;
    }

    std::vector<std::string> t_;
    int max_loop_;
    std::map<std::string, std::pair<std::size_t, std::size_t>> bodies_;
    std::map<std::string, ShaderCost> memo_;
    std::set<std::string> in_progress_;
};

}  // namespace

ShaderCost estimate_shader_cost(std::string_view source, int max_loop_iterations) {
    return Estimator(tokenize(preprocess(source)), std::max(max_loop_iterations, 1)).function("main");
}

}  // namespace puddle::bench
