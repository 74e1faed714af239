#include "brdf_file/brdf_glsl_es.h"

#include "brdf_file/brdf_file.h"
#include "brdf_file/glsl_es_lexicon.h"

#include <algorithm>
#include <cctype>
#include <map>
#include <set>
#include <stdexcept>

namespace m3055 {

namespace {

using namespace glsl_es;

// ---- the parser ---------------------------------------------------------------------

struct Edit {
    std::size_t offset;
    std::string text;
    std::size_t span;  // the wrapped expression's length (orders edits at one offset)
    bool closing;
};

// An expression: its type and where it is, and for the forms a conversion
// reaches into (a literal, a sign, parentheses) what it is made of.
struct Expr {
    enum Form { other, literal, sign, parens } form = other;
    Type type;
    std::size_t begin = 0, end = 0;
    const Token* token = nullptr;  // literal
    std::vector<Expr> parts;       // sign, parens: the operand
};

struct Function {
    Type result;
    std::vector<Type> params;
    std::vector<bool> converts;  // an `in` parameter (an out/inout argument is not converted)
};

class SyntaxError : public std::runtime_error {
public:
    SyntaxError(int line, const std::string& why) : std::runtime_error("line " + std::to_string(line) + ": " + why) {}
};

class Translator {
public:
    Translator(const std::string& text, const std::vector<std::pair<std::string, std::string>>& globals)
        : text_(text), tokens_(tokenize(text, macros_)) {
        scopes_.emplace_back();
        for (const auto& [type, name] : globals) scopes_.back()[name] = builtin_type(type);
    }

    GlslEsTranslation run() {
        GlslEsTranslation out;
        try {
            while (peek().kind != Token::end) external_declaration();
        } catch (const SyntaxError& e) {
            out.stopped = e.what();
        }
        out.text = apply();
        out.conversions = conversions_;
        out.redefined_builtins.assign(redefined_.begin(), redefined_.end());
        return out;
    }

private:
    const std::string& text_;
    std::set<std::string> macros_;
    std::vector<Token> tokens_;
    std::size_t pos_ = 0;
    std::vector<std::map<std::string, Type>> scopes_;
    std::map<std::string, std::vector<Function>> functions_;
    std::map<std::string, std::vector<std::pair<std::string, Type>>> structs_;
    std::set<std::string> redefined_;
    std::vector<Edit> edits_;
    Type return_type_;
    int conversions_ = 0;
    int depth_ = 0;

    // Nesting (parentheses, signs, blocks) beyond any real shader's stops the
    // translation instead of the stack: a file is untrusted input (1 MB at most).
    static constexpr int kMaxDepth = 200;
    struct Nested {
        Translator& t;
        Nested(Translator& translator, int line) : t(translator) {
            if (++t.depth_ > kMaxDepth) {
                --t.depth_;
                throw SyntaxError(line, "nested more than " + std::to_string(kMaxDepth) + " deep");
            }
        }
        ~Nested() { --t.depth_; }
    };

    // -- tokens
    const Token& peek(std::size_t ahead = 0) const { return tokens_[std::min(pos_ + ahead, tokens_.size() - 1)]; }
    bool is(const char* p, std::size_t ahead = 0) const {
        const Token& t = peek(ahead);
        return (t.kind == Token::punct || t.kind == Token::identifier) && t.text == p;
    }
    const Token& next() {
        const Token& t = peek();
        if (t.kind == Token::end) throw SyntaxError(t.line, "unexpected end of the shader block");
        ++pos_;
        return t;
    }
    void expect(const char* p) {
        if (!is(p)) throw SyntaxError(peek().line, std::string("expected '") + p + "' before '" + peek().text + "'");
        ++pos_;
    }
    bool accept(const char* p) {
        if (!is(p)) return false;
        ++pos_;
        return true;
    }
    std::size_t previous_end() const { return pos_ == 0 ? 0 : tokens_[pos_ - 1].end_offset; }

    // -- names
    Type type_named(const std::string& w) const {
        if (macros_.count(w)) return Type();
        const Type t = builtin_type(w);
        if (t.known()) return t;
        if (structs_.count(w)) {
            Type s = basic(Type::structure);
            s.name = w;
            return s;
        }
        return Type();
    }
    bool is_type_name(const Token& t) const { return t.kind == Token::identifier && type_named(t.text).known(); }
    Type variable(const std::string& name) const {
        if (macros_.count(name)) return Type();
        for (auto scope = scopes_.rbegin(); scope != scopes_.rend(); ++scope) {
            const auto it = scope->find(name);
            if (it != scope->end()) return it->second;
        }
        return Type();
    }
    void declare(const std::string& name, const Type& type) { scopes_.back()[name] = type; }

    // -- conversions
    void insert(std::size_t offset, const std::string& s, std::size_t span, bool closing) {
        edits_.push_back({offset, s, span, closing});
    }
    void wrap(const Expr& e, const std::string& constructor) {
        insert(e.begin, constructor + "(", e.end - e.begin, false);
        insert(e.end, ")", e.end - e.begin, true);
    }
    // Makes the implicit conversion of `e` to a floating (or, from int, to a uint)
    // type of e's shape explicit; `to` is floating or uinteger.
    void convert(const Expr& e, Type::Base to) {
        if (!e.type.numeric_int() || e.type.base == to) return;
        if (to == Type::uinteger && e.type.base != Type::integer) return;
        switch (e.form) {
            case Expr::literal:
                ++conversions_;
                // A suffix goes before any ")" closing at the same offset (apply()).
                if (to == Type::uinteger) insert(e.end, "u", 0, true);
                else if (e.token->decimal && e.token->kind == Token::int_literal) insert(e.end, ".0", 0, true);
                else wrap(e, "float");
                return;
            // Parentheses change nothing; a sign before a literal folds to a
            // constant either way (-1 -> -1.0). Anything else, ?: included, is
            // converted as a whole, where the desktop converts it: the same
            // value computed in another order (float(-i) vs -float(i)) can
            // compile to other instructions, and a contracted multiply-add then
            // rounds differently in the last bit.
            case Expr::parens: convert(e.parts[0], to); return;
            case Expr::sign:
                if (constant_operand(e)) return convert(e.parts[0], to);
                break;
            case Expr::other: break;
        }
        ++conversions_;
        const std::string scalar = to == Type::uinteger ? "uint" : "float";
        const std::string vector = to == Type::uinteger ? "uvec" : "vec";
        wrap(e, e.type.size == 1 ? scalar : vector + std::to_string(e.type.size));
    }
    // A sign before a literal (in parentheses or not).
    static bool constant_operand(const Expr& e) {
        const Expr* operand = &e.parts[0];
        while (operand->form == Expr::parens || operand->form == Expr::sign) operand = &operand->parts[0];
        return operand->form == Expr::literal;
    }
    // The conversion an initializer, assignment, return or `in` argument of type `to` needs.
    void convert_to(const Expr& e, const Type& to) {
        if (!to.known() || !e.type.known() || !e.type.numeric_int()) return;
        if (to.array != 0 || to.rows != 1 || to.size != e.type.size) return;
        if (to.base == Type::floating || (to.base == Type::uinteger && e.type.base == Type::integer))
            convert(e, to.base);
    }
    // Two operands of one operator: the int side converts to the other's base.
    void balance(const Expr& a, const Expr& b) {
        if (!a.type.known() || !b.type.known()) return;
        if (a.type.numeric_int() && b.type.numeric_float()) convert(a, Type::floating);
        else if (b.type.numeric_int() && a.type.numeric_float()) convert(b, Type::floating);
        else if (a.type.base == Type::integer && b.type.base == Type::uinteger) convert(a, Type::uinteger);
        else if (b.type.base == Type::integer && a.type.base == Type::uinteger) convert(b, Type::uinteger);
    }
    static Type::Base balanced_base(const Type& a, const Type& b) {
        if (a.base == Type::floating || b.base == Type::floating) return Type::floating;
        if (a.base == Type::uinteger || b.base == Type::uinteger) return Type::uinteger;
        return a.base;
    }

    // -- declarations
    void external_declaration() {
        if (accept(";")) return;
        if (is("precision")) {
            while (!accept(";")) next();
            return;
        }
        if (is("layout")) {
            next();
            skip_parenthesized();
        }
        declaration_or_function(true);
    }

    void skip_parenthesized() {
        expect("(");
        for (int depth = 1; depth > 0;) {
            const Token& t = next();
            if (t.text == "(") ++depth;
            if (t.text == ")") --depth;
        }
    }

    // qualifiers, then a type (a struct definition included); unknown if none.
    Type type_specifier(bool& is_const) {
        is_const = false;
        while (peek().kind == Token::identifier && is_qualifier(peek().text)) is_const |= next().text == "const";
        if (is("struct")) return struct_specifier();
        const Token& t = peek();
        Type type = type_named(t.text);
        if (!type.known()) throw SyntaxError(t.line, "expected a type before '" + t.text + "'");
        next();
        if (is("[")) type.array = array_size();
        return type;
    }

    int array_size() {
        expect("[");
        if (accept("]")) return -1;
        const Token& t = peek();
        const Expr e = expression();
        expect("]");
        return e.form == Expr::literal && t.kind == Token::int_literal && t.decimal ? std::stoi(t.text) : -1;
    }

    Type struct_specifier() {
        expect("struct");
        std::string name;
        if (peek().kind == Token::identifier && !is("{")) name = next().text;
        expect("{");
        std::vector<std::pair<std::string, Type>> members;
        while (!accept("}")) {
            bool is_const = false;
            const Type member = type_specifier(is_const);
            do {
                const Token& n = next();
                Type t = member;
                if (is("[")) t.array = array_size();
                members.push_back({n.text, t});
            } while (accept(","));
            expect(";");
        }
        structs_[name] = members;
        Type s = basic(Type::structure);
        s.name = name;
        return s;
    }

    // A declaration (variables, a struct, a prototype) or, at file scope, a function definition.
    void declaration_or_function(bool file_scope) {
        bool is_const = false;
        const Type type = type_specifier(is_const);
        if (accept(";")) return;  // "struct S { ... };"
        const Token& name = next();
        if (name.kind != Token::identifier) throw SyntaxError(name.line, "expected a name before '" + name.text + "'");
        if (file_scope && is("(")) return function(type, name.text);
        declarators(type, name.text);
    }

    void declarators(const Type& type, std::string name) {
        for (;;) {
            Type t = type;
            if (is("[")) t.array = array_size();
            if (accept("=")) convert_to(assignment(), t);
            declare(name, t);
            if (accept(";")) return;
            expect(",");
            const Token& n = next();
            if (n.kind != Token::identifier) throw SyntaxError(n.line, "expected a name before '" + n.text + "'");
            name = n.text;
        }
    }

    void function(const Type& result, const std::string& name) {
        expect("(");
        Function f;
        f.result = result;
        std::vector<std::pair<std::string, Type>> named;
        if (is("void") && is(")", 1)) next();
        while (!accept(")")) {
            bool converts = true;
            while (peek().kind == Token::identifier && is_qualifier(peek().text))
                if (const std::string q = next().text; q == "out" || q == "inout") converts = false;
            bool is_const = false;
            Type t = type_specifier(is_const);
            if (peek().kind == Token::identifier) {
                const std::string param = next().text;
                if (is("[")) t.array = array_size();
                named.push_back({param, t});
            }
            f.params.push_back(t);
            f.converts.push_back(converts);
            if (!is(")")) expect(",");
        }
        // A prototype and its definition are one function.
        std::vector<Function>& overloads = functions_[name];
        if (std::none_of(overloads.begin(), overloads.end(), [&](const Function& g) { return g.params == f.params; }))
            overloads.push_back(f);
        if ((builtins().count(name) || is_glsl_reserved(name)) && name != "main") redefined_.insert(name);
        if (accept(";")) return;
        scopes_.emplace_back();
        for (const auto& [param, t] : named) declare(param, t);
        return_type_ = result;
        compound_statement(false);
        scopes_.pop_back();
    }

    // -- statements
    void compound_statement(bool own_scope = true) {
        expect("{");
        if (own_scope) scopes_.emplace_back();
        while (!accept("}")) statement();
        if (own_scope) scopes_.pop_back();
    }

    bool declaration_ahead() const {
        const Token& t = peek();
        if (t.kind != Token::identifier) return false;
        if (is_qualifier(t.text) || t.text == "struct") return true;
        if (!is_type_name(t)) return false;
        // "vec3(...)" is a constructor; "float x", "float[2] x" and "S s" declare.
        return peek(1).kind == Token::identifier || is("[", 1);
    }

    void statement() {
        const Token& t = peek();
        const Nested nested(*this, t.line);
        if (is("{")) return compound_statement();
        if (accept(";")) return;
        if (accept("if")) {
            expect("(");
            expression();
            expect(")");
            scoped_statement();
            if (accept("else")) scoped_statement();
            return;
        }
        if (accept("while")) {
            expect("(");
            scopes_.emplace_back();
            condition();
            expect(")");
            statement();
            scopes_.pop_back();
            return;
        }
        if (accept("do")) {
            scoped_statement();
            expect("while");
            expect("(");
            expression();
            expect(")");
            expect(";");
            return;
        }
        if (accept("for")) {
            expect("(");
            scopes_.emplace_back();
            if (!accept(";")) {
                if (declaration_ahead()) declaration_or_function(false);
                else {
                    expression();
                    expect(";");
                }
            }
            if (!is(";")) condition();
            expect(";");
            if (!is(")")) expression();
            expect(")");
            statement();
            scopes_.pop_back();
            return;
        }
        if (accept("switch")) {
            expect("(");
            expression();
            expect(")");
            return compound_statement();
        }
        if (accept("case")) {
            expression();
            expect(":");
            return;
        }
        if (accept("default")) return expect(":");
        if (accept("return")) {
            if (!accept(";")) {
                convert_to(expression(), return_type_);
                expect(";");
            }
            return;
        }
        if (t.text == "break" || t.text == "continue" || t.text == "discard") {
            next();
            return expect(";");
        }
        if (declaration_ahead()) return declaration_or_function(false);
        expression();
        expect(";");
    }

    void scoped_statement() {
        scopes_.emplace_back();
        statement();
        scopes_.pop_back();
    }

    // A while's or for's condition: an expression, or "bool b = ...".
    void condition() {
        if (!declaration_ahead()) {
            expression();
            return;
        }
        bool is_const = false;
        const Type type = type_specifier(is_const);
        const std::string name = next().text;
        expect("=");
        convert_to(assignment(), type);
        declare(name, type);
    }

    // -- expressions (GLSL 4.20 §5.1's precedence)
    Expr expression() {
        Expr e = assignment();
        while (accept(",")) {
            Expr right = assignment();
            right.begin = e.begin;
            right.form = Expr::other;
            e = right;
        }
        return e;
    }

    Expr assignment() {
        Expr left = conditional();
        static const std::set<std::string> assigns = {"=", "+=", "-=", "*=", "/=", "%=", "<<=", ">>=", "&=", "|=", "^="};
        if (peek().kind != Token::punct || !assigns.count(peek().text)) return left;
        const std::string op = next().text;
        const Expr right = assignment();
        if (op == "=") convert_to(right, left.type);
        else if ((op == "+=" || op == "-=" || op == "*=" || op == "/=") && left.type.numeric_float()) convert(right, Type::floating);
        else if (left.type.base == Type::uinteger && right.type.base == Type::integer) convert(right, Type::uinteger);
        Expr e;
        e.type = left.type;
        e.begin = left.begin, e.end = right.end;
        return e;
    }

    Expr conditional() {
        Expr cond = binary(0);
        if (!accept("?")) return cond;
        Expr a = expression();
        expect(":");
        Expr b = assignment();
        balance(a, b);
        Expr e;
        e.begin = cond.begin, e.end = b.end;
        if (a.type.known() && b.type.known()) {
            e.type = a.type;
            if (a.type.base != b.type.base && a.type.array == 0 && b.type.array == 0)
                e.type.base = balanced_base(a.type, b.type);
        }
        return e;
    }

    // Binary operators, loosest first.
    static int precedence(const std::string& op) {
        static const std::map<std::string, int> levels = {
            {"||", 0}, {"^^", 1}, {"&&", 2}, {"|", 3},  {"^", 4},  {"&", 5},  {"==", 6}, {"!=", 6},
            {"<", 7},  {">", 7},  {"<=", 7}, {">=", 7}, {"<<", 8}, {">>", 8}, {"+", 9},  {"-", 9},
            {"*", 10}, {"/", 10}, {"%", 10}};
        const auto it = levels.find(op);
        return it == levels.end() ? -1 : it->second;
    }

    Expr binary(int min_level) {
        Expr left = unary();
        for (;;) {
            if (peek().kind != Token::punct) return left;
            const std::string op = peek().text;
            const int level = precedence(op);
            if (level < min_level || level < 0) return left;
            next();
            const Expr right = binary(level + 1);
            Expr e;
            e.begin = left.begin, e.end = right.end;
            e.type = binary_type(op, left, right);
            left = e;
        }
    }

    Type binary_type(const std::string& op, const Expr& a, const Expr& b) {
        if (op == "||" || op == "^^" || op == "&&") return basic(Type::boolean);
        const bool arithmetic = op == "+" || op == "-" || op == "*" || op == "/";
        const bool relational = op == "<" || op == ">" || op == "<=" || op == ">=" || op == "==" || op == "!=";
        if (arithmetic || relational) balance(a, b);
        if (relational) return basic(Type::boolean);
        if (!a.type.known() || !b.type.known() || a.type.array != 0 || b.type.array != 0) return Type();
        if (!arithmetic) return a.type.scalar() ? b.type : a.type;  // % << >> & | ^
        Type t = a.type.scalar() ? b.type : a.type;
        t.base = balanced_base(a.type, b.type);
        // Linear algebra (§5.10): matrix x vector, vector x matrix, matrix x matrix.
        if (op == "*" && a.type.rows > 1 && b.type.rows > 1) t = basic(Type::floating, b.type.size, a.type.rows);
        else if (op == "*" && a.type.rows > 1 && b.type.size > 1) t = basic(Type::floating, a.type.rows);
        else if (op == "*" && b.type.rows > 1 && a.type.size > 1) t = basic(Type::floating, b.type.size);
        return t;
    }

    Expr unary() {
        const Token& t = peek();
        const Nested nested(*this, t.line);
        if (t.kind == Token::punct && (t.text == "-" || t.text == "+" || t.text == "!" || t.text == "~" ||
                                        t.text == "++" || t.text == "--")) {
            next();
            Expr operand = unary();
            Expr e;
            e.begin = t.begin, e.end = operand.end;
            e.type = t.text == "!" ? basic(Type::boolean) : operand.type;
            if (t.text == "-" || t.text == "+") {
                e.form = Expr::sign;
                e.parts = {operand};
            }
            return e;
        }
        return postfix(primary());
    }

    Expr postfix(Expr e) {
        for (;;) {
            if (accept("[")) {
                expression();
                expect("]");
                Type t = e.type;
                if (t.array != 0) t.array = 0;
                else if (t.rows > 1) t = basic(Type::floating, t.rows);
                else if (t.size > 1) t.size = 1;
                else t = Type();
                e = Expr{Expr::other, t, e.begin, previous_end(), nullptr, {}};
            } else if (accept(".")) {
                const Token& field = next();
                Type t;
                if (field.text == "length" && is("(")) {
                    expect("(");
                    expect(")");
                    t = basic(Type::integer);
                } else if (e.type.base == Type::structure && e.type.array == 0) {
                    for (const auto& [member, type] : structs_[e.type.name])
                        if (member == field.text) t = type;
                } else if (e.type.known() && e.type.array == 0 && e.type.rows == 1 && field.text.size() <= 4) {
                    t = e.type;
                    t.size = int(field.text.size());
                }
                e = Expr{Expr::other, t, e.begin, previous_end(), nullptr, {}};
            } else if (is("++") || is("--")) {
                next();
                e = Expr{Expr::other, e.type, e.begin, previous_end(), nullptr, {}};
            } else {
                return e;
            }
        }
    }

    Expr primary() {
        const Token& t = next();
        Expr e;
        e.begin = t.begin, e.end = t.end_offset;
        switch (t.kind) {
            case Token::int_literal:
            case Token::uint_literal:
                e.form = Expr::literal;
                e.token = &t;
                e.type = basic(t.kind == Token::int_literal ? Type::integer : Type::uinteger);
                return e;
            case Token::float_literal: e.type = basic(Type::floating); return e;
            case Token::end: throw SyntaxError(t.line, "unexpected end of the shader block");
            case Token::punct:
                if (t.text != "(") throw SyntaxError(t.line, "unexpected '" + t.text + "'");
                e.parts = {expression()};
                expect(")");
                e.form = Expr::parens;
                e.type = e.parts[0].type;
                e.end = previous_end();
                return e;
            case Token::identifier: break;
        }
        if (t.text == "true" || t.text == "false") {
            e.type = basic(Type::boolean);
            return e;
        }
        if (is_type_name(t)) {  // a constructor: "vec3(...)", "float[2](...)", "S(...)"
            Type type = type_named(t.text);
            if (is("[")) type.array = array_size();
            std::vector<Expr> args = arguments();
            if (type.array != 0) {
                for (const Expr& a : args) convert_to(a, element_of(type));
                if (type.array < 0) type.array = int(args.size());
            } else if (type.base == Type::structure) {
                const auto& members = structs_[type.name];
                if (members.size() == args.size())
                    for (std::size_t i = 0; i < args.size(); ++i) convert_to(args[i], members[i].second);
            }
            e.type = type;
            e.end = previous_end();
            return e;
        }
        if (is("(")) {
            std::vector<Expr> args = arguments();
            e.type = call(t.text, args);
            e.end = previous_end();
            return e;
        }
        e.type = variable(t.text);
        return e;
    }

    std::vector<Expr> arguments() {
        expect("(");
        std::vector<Expr> args;
        if (is("void") && is(")", 1)) next();
        while (!accept(")")) {
            args.push_back(assignment());
            if (!is(")")) expect(",");
        }
        return args;
    }

    // A call's type, converting its arguments as the overload the desktop
    // compiler picks needs (§6.1: an exact match, else the one that matches
    // with conversions; none or several: nothing is converted).
    Type call(const std::string& name, const std::vector<Expr>& args) {
        if (macros_.count(name)) return Type();
        const auto user = functions_.find(name);
        if (user != functions_.end()) return user_call(user->second, args);
        const auto builtin = builtins().find(name);
        if (builtin == builtins().end()) return Type();
        return builtin_call(builtin->second, args);
    }

    Type user_call(const std::vector<Function>& overloads, const std::vector<Expr>& args) {
        for (const Expr& a : args)
            if (!a.type.known()) return Type();
        const Function* chosen = nullptr;
        int matches = 0;
        for (const Function& f : overloads) {
            if (f.params.size() != args.size()) continue;
            bool exact = true, convertible = true;
            for (std::size_t i = 0; i < args.size(); ++i) {
                const Type& p = f.params[i];
                const Type& a = args[i].type;
                if (p == a) continue;
                exact = false;
                const bool widens = f.converts[i] && a.numeric_int() && p.array == 0 && p.rows == 1 && p.size == a.size &&
                                    (p.base == Type::floating || (p.base == Type::uinteger && a.base == Type::integer));
                if (!widens) convertible = false;
            }
            if (exact) return f.result;
            if (convertible) chosen = &f, ++matches;
        }
        if (matches != 1) return Type();
        for (std::size_t i = 0; i < args.size(); ++i) convert_to(args[i], chosen->params[i]);
        return chosen->result;
    }

    Type builtin_call(Builtin kind, const std::vector<Expr>& args) {
        if (args.empty()) return Type();
        for (const Expr& a : args)
            if (!a.type.known() || a.type.array != 0) return Type();
        int widest = 1;
        bool any_float = false;
        for (const Expr& a : args) {
            if (a.type.rows == 1) widest = std::max(widest, a.type.size);
            any_float |= a.type.base == Type::floating;
        }
        // Every float-taking argument: mix's bool selector (§8.3) is not one.
        auto to_float = [&](bool only_when_mixed) {
            if (only_when_mixed && !any_float) return;
            for (std::size_t i = 0; i < args.size(); ++i)
                if (args[i].type.base != Type::boolean) convert(args[i], Type::floating);
        };
        const Type& first = args[0].type;
        switch (kind) {
            case Builtin::component_float:
                to_float(false);
                return basic(Type::floating, widest);
            case Builtin::component_number:
                if (any_float) {
                    to_float(true);
                    return basic(Type::floating, widest);
                }
                return basic(first.base, widest);
            case Builtin::scalar_float: to_float(false); return basic(Type::floating);
            case Builtin::like_first: to_float(false); return basic(Type::floating, first.size);
            case Builtin::cross: to_float(false); return basic(Type::floating, 3);
            case Builtin::compare_vectors: to_float(true); return basic(Type::boolean, first.size);
            case Builtin::any_all: return basic(Type::boolean);
            case Builtin::not_vector: return first;
            case Builtin::bool_of_float: to_float(false); return basic(Type::boolean, first.size);
            case Builtin::matrix_same: return first;
            case Builtin::transpose: return basic(Type::floating, first.rows, first.size);
            case Builtin::determinant: return basic(Type::floating);
        }
        return Type();
    }

    // -- output
    std::string apply() {
        // At one offset: closing parentheses first (innermost first), then the
        // openings (outermost first), so nested conversions nest.
        std::stable_sort(edits_.begin(), edits_.end(), [](const Edit& a, const Edit& b) {
            if (a.offset != b.offset) return a.offset < b.offset;
            if (a.closing != b.closing) return a.closing;
            return a.closing ? a.span < b.span : a.span > b.span;
        });
        std::string out;
        std::size_t at = 0;
        for (const Edit& e : edits_) {
            out.append(text_, at, e.offset - at);
            out += e.text;
            at = e.offset;
        }
        out.append(text_, at, std::string::npos);
        return out;
    }
};

}  // namespace

GlslEsTranslation translate_glsl_es(const std::string& block,
                                    const std::vector<std::pair<std::string, std::string>>& globals) {
    return Translator(block, globals).run();
}

}  // namespace m3055
