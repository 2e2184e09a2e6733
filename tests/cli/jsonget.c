/* jsonget: print one value of a JSON file, for the CLI tests.
 *
 *   jsonget FILE                 exit 0 if FILE is valid JSON, else 2
 *   jsonget [-p N] FILE PATH     print the value at PATH ("a.b.0.c": object
 *                                keys and array indices separated by dots);
 *                                numbers with %.17g, or %.Nf with -p N;
 *                                strings raw; true/false/null; objects and
 *                                arrays as compact JSON; an array's length
 *                                with PATH ending in ".length". Exit 1 if
 *                                the path is not there. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <cjson/cJSON.h>

static char *slurp(const char *path)
{
    FILE *fp = fopen(path, "rb");
    char *buf;
    long n;
    if (!fp)
        return NULL;
    fseek(fp, 0, SEEK_END);
    n = ftell(fp);
    rewind(fp);
    buf = malloc((size_t)n + 1);
    if (buf && fread(buf, 1, (size_t)n, fp) != (size_t)n) {
        free(buf);
        buf = NULL;
    }
    if (buf)
        buf[n] = '\0';
    fclose(fp);
    return buf;
}

/* Walk one dot-separated component at a time. */
static const cJSON *walk(const cJSON *node, const char *path, int *want_length)
{
    char key[256];
    *want_length = 0;
    while (node && *path) {
        size_t n = strcspn(path, ".");
        if (n >= sizeof key)
            return NULL;
        memcpy(key, path, n);
        key[n] = '\0';
        path += n + (path[n] == '.');
        if (cJSON_IsArray(node) && !strcmp(key, "length") && !*path) {
            *want_length = 1;
            return node;
        }
        if (cJSON_IsArray(node))
            node = cJSON_GetArrayItem(node, atoi(key));
        else
            node = cJSON_GetObjectItemCaseSensitive(node, key);
    }
    return node;
}

static int print_value(const cJSON *v, int prec, int want_length)
{
    if (want_length)
        printf("%d\n", cJSON_GetArraySize(v));
    else if (cJSON_IsNumber(v) && prec >= 0)
        printf("%.*f\n", prec, v->valuedouble);
    else if (cJSON_IsNumber(v))
        printf("%.17g\n", v->valuedouble);
    else if (cJSON_IsString(v))
        printf("%s\n", v->valuestring);
    else if (cJSON_IsBool(v))
        printf("%s\n", cJSON_IsTrue(v) ? "true" : "false");
    else if (cJSON_IsNull(v))
        printf("null\n");
    else {
        char *s = cJSON_PrintUnformatted(v);
        if (!s)
            return 2;
        printf("%s\n", s);
        cJSON_free(s);
    }
    return 0;
}

int main(int argc, char **argv)
{
    int prec = -1, i = 1, rc, want_length;
    char *text;
    cJSON *root;
    const cJSON *v;
    if (argc > 2 && !strcmp(argv[1], "-p")) {
        prec = atoi(argv[2]);
        i = 3;
    }
    if (argc - i < 1 || argc - i > 2) {
        fprintf(stderr, "usage: jsonget [-p N] FILE [PATH]\n");
        return 2;
    }
    if (!(text = slurp(argv[i]))) {
        fprintf(stderr, "jsonget: cannot read %s\n", argv[i]);
        return 2;
    }
    root = cJSON_Parse(text);
    free(text);
    if (!root) {
        fprintf(stderr, "jsonget: %s is not valid JSON\n", argv[i]);
        return 2;
    }
    rc = 0;
    if (argc - i == 2) {
        v = walk(root, argv[i + 1], &want_length);
        if (!v) {
            fprintf(stderr, "jsonget: %s: no value at '%s'\n", argv[i], argv[i + 1]);
            rc = 1;
        } else {
            rc = print_value(v, prec, want_length);
        }
    }
    cJSON_Delete(root);
    return rc;
}
