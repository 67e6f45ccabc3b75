/* json.h — the one JSON string writer of libvigen (the show and check
 * reports).  Output is always valid JSON text in UTF-8 (RFC 8259): '"' and
 * '\' escaped, control characters U+0000..U+001F escaped (\b \f \n \r \t, the
 * others as \u00XX), and every byte that does not start a well-formed UTF-8
 * sequence (RFC 3629: no overlong forms, no surrogates, nothing above
 * U+10FFFF) written as \ufffd, one per byte, since names and entries come
 * from untrusted files. */
#ifndef VIGEN_REPORT_JSON_H
#define VIGEN_REPORT_JSON_H

#include <stdio.h>
#include "vigen/error.h"
#include "support/strbuf.h"

/* Appends text as a quoted JSON string. */
void vigen_json_string(vigen_strbuf *sb, const char *text);

/* Writes text as a quoted JSON string to out. */
void vigen_json_write_string(FILE *out, const char *text);

#endif
