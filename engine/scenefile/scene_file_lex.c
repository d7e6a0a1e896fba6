/* Bytes to tokens, and the numbers and messages every other part uses. */
#include <ctype.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "scene_file_private.h"

void sf_lexer_init(sf_lexer_t *lexer, const char *text, size_t length, const char *file_name,
                   scene_file_error_t *error) {
    *lexer = (sf_lexer_t){
        .text = text,
        .length = length,
        .where = {1, 1},
        .file_name = file_name != NULL ? file_name : "<memory>",
        .error = error,
    };
}

bool sf_fail(sf_lexer_t *lexer, sf_where_t where, const char *format, ...) {
    if (lexer->failed) return false;
    lexer->failed = true;
    scene_file_error_t *error = lexer->error;
    if (error == NULL) return false;
    int used = snprintf(error->message, sizeof error->message, "%s:%zu:%zu: ", lexer->file_name,
                        where.line, where.column);
    if (used >= 0 && (size_t)used < sizeof error->message) {
        va_list args;
        va_start(args, format);
        vsnprintf(error->message + used, sizeof error->message - (size_t)used, format, args);
        va_end(args);
    }
    error->line = where.line;
    error->column = where.column;
    return false;
}

/* Bytes that end a word. Control bytes end it too: they are refused on their
 * own, so that the message points at them. */
static bool is_delimiter(unsigned char c) {
    return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == ';' || c == '{' || c == '}' ||
           c == '#' || c < 0x20 || c == 0x7f;
}

static void advance(sf_lexer_t *lexer) {
    if (lexer->text[lexer->offset] == '\n') {
        lexer->where.line++;
        lexer->where.column = 1;
    } else {
        lexer->where.column++;
    }
    lexer->offset++;
}

sf_token_t sf_lex_next(sf_lexer_t *lexer) {
    /* Spaces and comments (to the end of the line, which stays a token). */
    while (lexer->offset < lexer->length) {
        char c = lexer->text[lexer->offset];
        if (c == ' ' || c == '\t' || c == '\r') {
            advance(lexer);
        } else if (c == '#') {
            while (lexer->offset < lexer->length && lexer->text[lexer->offset] != '\n')
                advance(lexer);
        } else {
            break;
        }
    }
    sf_token_t token = {TOKEN_END, lexer->text + lexer->offset, 0, lexer->where};
    if (lexer->offset >= lexer->length) return token;
    unsigned char c = (unsigned char)lexer->text[lexer->offset];
    token.length = 1;
    switch (c) {
    case '\n': token.kind = TOKEN_NEWLINE; break;
    case ';': token.kind = TOKEN_SEMICOLON; break;
    case '{': token.kind = TOKEN_OPEN; break;
    case '}': token.kind = TOKEN_CLOSE; break;
    default:
        if (is_delimiter(c)) {
            token.kind = TOKEN_BAD_BYTE;
            break;
        }
        token.kind = TOKEN_WORD;
        token.length = 0;
        while (lexer->offset + token.length < lexer->length &&
               !is_delimiter((unsigned char)lexer->text[lexer->offset + token.length]))
            token.length++;
        for (size_t i = 0; i < token.length; i++) advance(lexer);
        return token;
    }
    advance(lexer);
    return token;
}

/* Words are shown quoted, with anything unprintable escaped, and cut after
 * 40 bytes so that a message stays one readable line. */
static void describe_word(const sf_token_t *token, char *buffer, size_t size) {
    size_t used = 0;
    const size_t shown = token->length < 40 ? token->length : 40;
    used += (size_t)snprintf(buffer, size, "\"");
    for (size_t i = 0; i < shown && used + 8 < size; i++) {
        unsigned char c = (unsigned char)token->text[i];
        if (c == '"' || c == '\\') {
            used += (size_t)snprintf(buffer + used, size - used, "\\%c", c);
        } else if (c < 0x20 || c >= 0x7f) {
            used += (size_t)snprintf(buffer + used, size - used, "\\x%02x", c);
        } else {
            buffer[used++] = (char)c;
            buffer[used] = '\0';
        }
    }
    snprintf(buffer + used, size - used, "%s\"", token->length > shown ? "..." : "");
}

const char *sf_describe(const sf_token_t *token, char *buffer, size_t size) {
    switch (token->kind) {
    case TOKEN_WORD: describe_word(token, buffer, size); break;
    case TOKEN_NEWLINE: snprintf(buffer, size, "the end of the line"); break;
    case TOKEN_SEMICOLON: snprintf(buffer, size, "';'"); break;
    case TOKEN_OPEN: snprintf(buffer, size, "'{'"); break;
    case TOKEN_CLOSE: snprintf(buffer, size, "'}'"); break;
    case TOKEN_END: snprintf(buffer, size, "the end of the file"); break;
    case TOKEN_BAD_BYTE:
        snprintf(buffer, size, "the control byte 0x%02x", (unsigned char)token->text[0]);
        break;
    }
    return buffer;
}

bool sf_token_is(const sf_token_t *token, const char *word) {
    size_t n = strlen(word);
    return token->kind == TOKEN_WORD && token->length == n && memcmp(token->text, word, n) == 0;
}

bool sf_is_name(const sf_token_t *token) {
    if (token->kind != TOKEN_WORD || token->length == 0 || token->length > SCENE_FILE_NAME_MAX)
        return false;
    unsigned char first = (unsigned char)token->text[0];
    if (!(isalpha(first) || first == '_') || first >= 0x80) return false;
    for (size_t i = 1; i < token->length; i++) {
        unsigned char c = (unsigned char)token->text[i];
        if (c >= 0x80 || !(isalnum(c) || c == '_' || c == '.' || c == '-')) return false;
    }
    return true;
}

/* The length of the decimal number at the start of text[0..length): sign,
 * digits with at most one point (at least one digit), exponent. 0 when there
 * is none. strtod alone would also take "inf", "nan" and hexadecimal. */
static size_t decimal_length(const char *text, size_t length, bool allow_sign) {
    size_t i = 0, digits = 0;
    if (allow_sign && i < length && (text[i] == '+' || text[i] == '-')) i++;
    while (i < length && isdigit((unsigned char)text[i])) i++, digits++;
    if (i < length && text[i] == '.') {
        i++;
        while (i < length && isdigit((unsigned char)text[i])) i++, digits++;
    }
    if (digits == 0) return 0;
    if (i < length && (text[i] == 'e' || text[i] == 'E')) {
        size_t j = i + 1;
        if (j < length && (text[j] == '+' || text[j] == '-')) j++;
        size_t exponent_digits = 0;
        while (j < length && isdigit((unsigned char)text[j])) j++, exponent_digits++;
        if (exponent_digits == 0) return 0;
        i = j;
    }
    return i;
}

/* strtod of text[0..length) (a checked decimal), through a terminated copy. A
 * number longer than the copy is refused as not finite would be misleading,
 * so very long digit strings are a syntax error. */
static bool convert(const char *text, size_t length, double *value) {
    char copy[128];
    if (length >= sizeof copy) return false;
    memcpy(copy, text, length);
    copy[length] = '\0';
    *value = strtod(copy, NULL);
    return true;
}

sf_number_status_t sf_read_number(const sf_token_t *token, bool allow_degrees, double *value) {
    if (token->kind != TOKEN_WORD) return SF_NUMBER_SYNTAX;
    const char *text = token->text;
    size_t length = token->length;
    bool degrees = false;
    if (allow_degrees && length > 3 && memcmp(text + length - 3, "deg", 3) == 0) {
        degrees = true;
        length -= 3;
    }
    size_t numerator = decimal_length(text, length, true);
    if (numerator == 0) return SF_NUMBER_SYNTAX;
    double top = 0.0, bottom = 1.0;
    if (!convert(text, numerator, &top)) return SF_NUMBER_SYNTAX;
    if (numerator < length) {
        /* A fraction: "1/60". */
        if (text[numerator] != '/') return SF_NUMBER_SYNTAX;
        const char *rest = text + numerator + 1;
        size_t rest_length = length - numerator - 1;
        size_t denominator = decimal_length(rest, rest_length, false);
        if (denominator == 0 || denominator != rest_length) return SF_NUMBER_SYNTAX;
        if (!convert(rest, denominator, &bottom)) return SF_NUMBER_SYNTAX;
        if (!isfinite(bottom)) return SF_NUMBER_NOT_FINITE;
        if (bottom == 0.0) return SF_NUMBER_ZERO_DENOMINATOR;
    }
    double result = top / bottom;
    if (degrees) result *= M_PI / 180.0;
    if (!isfinite(top) || !isfinite(result)) return SF_NUMBER_NOT_FINITE;
    *value = result;
    return SF_NUMBER_OK;
}

bool sf_read_integer(const sf_token_t *token, uint64_t max, bool allow_hex, uint64_t *value) {
    if (token->kind != TOKEN_WORD || token->length == 0) return false;
    const char *text = token->text;
    size_t length = token->length;
    unsigned base = 10;
    if (allow_hex && length > 2 && text[0] == '0' && (text[1] == 'x' || text[1] == 'X')) {
        base = 16;
        text += 2;
        length -= 2;
    }
    uint64_t result = 0;
    for (size_t i = 0; i < length; i++) {
        unsigned char c = (unsigned char)text[i];
        unsigned digit;
        if (isdigit(c)) {
            digit = (unsigned)(c - '0');
        } else if (base == 16 && isxdigit(c)) {
            digit = (unsigned)(tolower(c) - 'a' + 10);
        } else {
            return false;
        }
        if (digit > max || result > (max - digit) / base) return false; /* would pass max */
        result = result * base + digit;
    }
    *value = result;
    return true;
}

void sf_reserve(void **array, size_t *capacity, size_t needed, size_t element_size) {
    if (needed <= *capacity) return;
    size_t grown = *capacity < 8 ? 8 : *capacity;
    while (grown < needed) grown *= 2;
    void *moved = realloc(*array, grown * element_size);
    if (moved == NULL) {
        /* The limits keep a file far below this; running out is the machine's
         * problem, as it is for the engine (memory.c). */
        fprintf(stderr, "scene file: out of memory growing an array to %zu elements\n", grown);
        abort();
    }
    *array = moved;
    *capacity = grown;
}
