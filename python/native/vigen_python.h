/* vigen_python.h — the C interface of the Python package (libvigen_python.so).
 *
 * A flat API over libvigen, the runtime and the problem collection, made for
 * a caller that loads the library with cffi in ABI mode (python/vigen/
 * _native.py declares these functions from this file, without the lines
 * that start with '#'): plain C types only, no callbacks into the caller,
 * every text handed out allocated with malloc and freed by the caller with
 * vigen_python_free (or vigen_python_result_clear).
 *
 * Each call does what one command of the command line does, through the same
 * library functions, with the same caps of the Lua sandbox (memory,
 * instructions), of the working precision and of the options' ranges, and
 * the same messages: a failure gives the one line `vigen COMMAND` prints on
 * standard error ("vigen check: x.lua: ...") and its status code, whose
 * exit status (2 bad input, 3 a resource limit) the caller turns into its
 * exception.  What the command line guards at the level of the process (the
 * wall-clock cap, the cap on the arithmetic's memory, FLINT's aborts, the
 * signals) is not installed: a library must not end the process it is
 * loaded into.
 *
 * The calls hold one lock: libvigen keeps process-wide settings (the caps,
 * the warning hook), so calls from several threads run one at a time.
 * Nothing is printed: warnings of the library are collected into the
 * result. */

/* Options are texts, as on the command line: NULL when not given, else a
 * whole number checked as the command line checks it (the same range, the
 * same message: "--digits takes a whole number from 1 to 100000, not
 * '0'"). */

/* What a call gives back.  Zero it (or clear it) before a call; the call
 * fills it; vigen_python_result_clear frees its texts. */
typedef struct {
    int status;         /* VIGEN_OK (0) or a VIGEN_E_* code of vigen/status.def */
    int exit_status;    /* the command line's exit status: 0, 1 (a check's verdict), 2 or 3 */
    char *text;         /* the result: JSON, a tableau file, LaTeX, ... (NULL on failure) */
    char *extra;        /* a second result where a call says so (NULL otherwise) */
    char *message;      /* on failure: the one line the command line prints (NULL otherwise) */
    char *warnings;     /* the library's warnings, one a line ("vigen: warning: ..."), or NULL */
} vigen_python_result;

/* Frees the texts of r and zeroes it. */
void vigen_python_result_clear(vigen_python_result *r);
/* Frees a text the library handed out (NULL: nothing). */
void vigen_python_free(void *p);

/* The version of vigen ("0.1.0"; static). */
const char *vigen_python_version(void);
/* The words of a status code ("syntax error"; static). */
const char *vigen_python_status_name(int status);

/* The caps every later call runs under, the global options of the command
 * line: --max-memory MIB (Lua memory, 1..1048576), --max-instructions N (Lua
 * instructions per call, 1..10^12), --max-prec BITS (working precision,
 * 64..2^40).  NULL leaves a cap as it is.  A value out of range fails with
 * the command line's message (VIGEN_E_USAGE) and changes no cap. */
int vigen_python_set_caps(vigen_python_result *r, const char *max_memory_mib, const char *max_instructions,
                          const char *max_prec);

/* `vigen list --json`: text = the JSON object. */
int vigen_python_list(vigen_python_result *r);

/* operand as `vigen` resolves it (a file, or a method name of the library,
 * vigen/library.h): text = the path.  command names the command in the
 * message ("show", "check", ...; "" for none: "vigen: ..."). */
int vigen_python_resolve(vigen_python_result *r, const char *command, const char *operand);

/* `vigen check FILE --json [--against FILE2] [--max-order P] [--prec BITS]`:
 * text = the JSON object, exit_status = the verdict (0 or 1).  against NULL:
 * not given. */
int vigen_python_check(vigen_python_result *r, const char *file, const char *against, const char *max_order,
                       const char *prec);

/* `vigen compare FILE... --format FORMAT [--max-order P]`: files one a line;
 * format "text", "latex" or "json"; text = the table. */
int vigen_python_compare(vigen_python_result *r, const char *files, const char *format, const char *max_order);

/* `vigen generate SPEC --digits N`: text = the tableau file (what -o
 * writes), extra = the tableau as `vigen show --format json` prints it (the
 * entries as decimal texts), message = the summary line the command prints
 * on standard error when it succeeds. */
int vigen_python_generate(vigen_python_result *r, const char *spec, const char *digits);

/* `vigen show FILE --format FORMAT --digits N`: text = what it prints
 * (format "text", "latex", "json" or "lua"). */
int vigen_python_show(vigen_python_result *r, const char *file, const char *format, const char *digits);

/* Writes text to path atomically, as `vigen generate -o` does: the file is
 * the old one or the new one, never a part; nothing is left on failure.
 * command names the command in the message. */
int vigen_python_write_file(vigen_python_result *r, const char *command, const char *path, const char *text);
