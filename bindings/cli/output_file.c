/* hdt-triangulate: outputs that appear whole or not at all. */
/* realpath: POSIX.1-2008, which glibc declares with the XSI option. */
#define _XOPEN_SOURCE 700

#include "output_file.h"

#include "cli_util.h"

#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

/* ---- Removing the temporary files when a signal ends the program ---- */

#define MAX_TEMPS 4
/* Paths the handler unlinks: set before a file exists, cleared (under a
   blocked signal mask) before the path is freed or renamed. */
static char *volatile temp_paths[MAX_TEMPS];
static const int handled_signals[] = {SIGINT, SIGTERM, SIGHUP, SIGPIPE};
#define N_SIGNALS (sizeof handled_signals / sizeof handled_signals[0])
static int handlers_installed;

static void on_signal(int sig) {
  for (int i = 0; i < MAX_TEMPS; ++i)
    if (temp_paths[i]) unlink(temp_paths[i]);
  signal(sig, SIG_DFL);
  raise(sig);
}

static void block_signals(sigset_t *old) {
  sigset_t set;
  sigemptyset(&set);
  for (size_t i = 0; i < N_SIGNALS; ++i) sigaddset(&set, handled_signals[i]);
  sigprocmask(SIG_BLOCK, &set, old);
}

static void install_handlers(void) {
  if (handlers_installed) return;
  handlers_installed = 1;
  for (size_t i = 0; i < N_SIGNALS; ++i) {
    struct sigaction previous;
    if (sigaction(handled_signals[i], NULL, &previous) != 0) continue;
    if (previous.sa_handler == SIG_IGN) continue; /* e.g. nohup: stay ignored */
    struct sigaction action;
    memset(&action, 0, sizeof action);
    action.sa_handler = on_signal;
    sigemptyset(&action.sa_mask);
    for (size_t k = 0; k < N_SIGNALS; ++k) sigaddset(&action.sa_mask, handled_signals[k]);
    sigaction(handled_signals[i], &action, NULL);
  }
}

static int register_temp(char *path) {
  sigset_t old;
  block_signals(&old);
  int done = 0;
  for (int i = 0; i < MAX_TEMPS && !done; ++i)
    if (!temp_paths[i]) {
      temp_paths[i] = path;
      done = 1;
    }
  sigprocmask(SIG_SETMASK, &old, NULL);
  return done;
}

static void unregister_temp(const char *path) {
  sigset_t old;
  block_signals(&old);
  for (int i = 0; i < MAX_TEMPS; ++i)
    if (temp_paths[i] == path) temp_paths[i] = NULL;
  sigprocmask(SIG_SETMASK, &old, NULL);
}

/* ---- Outputs ---- */

static char *copy_string(const char *s) {
  char *c = cli_alloc(strlen(s) + 1, 1);
  if (c) strcpy(c, s);
  return c;
}

/* The directory holding `path`'s file, for messages: "." for a bare name,
   "/" for a file in the root. */
static void directory_of(const char *path, char *out, size_t size) {
  const char *slash = strrchr(path, '/');
  if (!slash) snprintf(out, size, ".");
  else if (slash == path) snprintf(out, size, "/");
  else snprintf(out, size, "%.*s", (int)(slash - path), path);
}

static int current_umask(void) {
  const mode_t mask = umask(022);
  umask(mask);
  return (int)mask;
}

/* The temporary file next to destination: "DIR/.BASE.XXXXXX". */
static int open_temp(output_file *o) {
  const char *slash = strrchr(o->destination, '/');
  const size_t dir_length = slash ? (size_t)(slash - o->destination) + 1 : 0;
  const char *base = o->destination + dir_length;
  char *path = cli_alloc(dir_length + strlen(base) + 16, 1);
  if (!path) return 0;
  memcpy(path, o->destination, dir_length);
  sprintf(path + dir_length, ".%s.XXXXXX", base);
  install_handlers();
  /* Created and registered with the signals blocked: a signal either comes
     before the file exists or finds it registered. */
  sigset_t old;
  block_signals(&old);
  const int fd = mkstemp(path);
  const int e = errno;
  const int registered = fd >= 0 && register_temp(path);
  if (fd >= 0 && !registered) {
    unlink(path);
    close(fd);
  }
  sigprocmask(SIG_SETMASK, &old, NULL);
  if (!registered) {
    if (fd < 0) {
      /* The usual causes are the directory's: missing, not writable,
         read-only; name it, with the destination as resolved. */
      char directory[PATH_MAX];
      directory_of(o->destination, directory, sizeof directory);
      cli_error("cannot write %s: cannot create a temporary file in the directory '%s': %s", o->name, directory,
                strerror(e));
    } else
      cli_error("%s: too many outputs", o->name);
    free(path);
    return 0;
  }
  o->temp_path = path;
  o->f = fdopen(fd, "w");
  if (!o->f) {
    cli_error("%s: %s", o->name, strerror(errno));
    close(fd);
    return 0;
  }
  return 1;
}

int output_open(output_file *o, const char *name) {
  memset(o, 0, sizeof *o);
  o->name = (name && strcmp(name, "-") != 0) ? name : "-";
  if (strcmp(o->name, "-") != 0) {
    struct stat st;
    if (stat(o->name, &st) == 0) {
      if (S_ISDIR(st.st_mode)) {
        cli_error("cannot write %s: it is a directory", o->name);
        return 0;
      }
      if (S_ISREG(st.st_mode)) {
        /* Follow a symbolic link: the file it names is replaced. */
        char *resolved = realpath(o->name, NULL);
        o->destination = resolved ? resolved : copy_string(o->name);
        if (!resolved && !o->destination) return 0;
        o->mode = (int)(st.st_mode & 07777);
      } else {
        o->stream_to_path = 1; /* /dev/null, a FIFO, ...: written in place */
      }
    } else if (errno == ENOENT) {
      struct stat lst;
      if (lstat(o->name, &lst) == 0) { /* a dangling symbolic link */
        cli_error("cannot write %s: a symbolic link to a missing file", o->name);
        return 0;
      }
      o->destination = copy_string(o->name);
      if (!o->destination) return 0;
      o->mode = 0666 & ~current_umask();
    } else {
      /* ENOTDIR, EACCES, ELOOP: a part of the directory's path is at fault. */
      const int e = errno;
      char directory[PATH_MAX];
      directory_of(o->name, directory, sizeof directory);
      if (e == ENOTDIR || e == EACCES || e == ELOOP)
        cli_error("cannot write %s: the directory '%s': %s", o->name, directory, strerror(e));
      else
        cli_error("cannot write %s: %s", o->name, strerror(e));
      return 0;
    }
  }
  if (o->destination) {
    if (open_temp(o)) return 1;
    output_discard(o);
    return 0;
  }
  o->f = open_memstream(&o->buffer, &o->size);
  if (!o->f) {
    cli_error("%s: %s", o->name, strerror(errno));
    return 0;
  }
  return 1;
}

int output_finish(output_file *o) {
  if (!o->f) return 0;
  int ok = fflush(o->f) == 0 && !ferror(o->f);
  int e = errno;
  if (ok && o->temp_path && fchmod(fileno(o->f), (mode_t)o->mode) != 0) {
    ok = 0;
    e = errno;
  }
  if (fclose(o->f) != 0 && ok) {
    ok = 0;
    e = errno;
  }
  o->f = NULL;
  if (!ok) cli_error("cannot write %s: %s", o->name, strerror(e));
  return ok;
}

static int write_all(FILE *f, const char *data, size_t size) {
  return fwrite(data, 1, size, f) == size && fflush(f) == 0 && !ferror(f);
}

int output_commit(output_file *o) {
  int ok = 1;
  if (o->temp_path) {
    unregister_temp(o->temp_path);
    if (rename(o->temp_path, o->destination) != 0) {
      const int e = errno;
      char directory[PATH_MAX];
      directory_of(o->destination, directory, sizeof directory);
      cli_error("cannot replace %s: renaming the finished temporary file onto it in the directory '%s': %s",
                o->name, directory, strerror(e));
      unlink(o->temp_path);
      ok = 0;
    }
  } else if (o->stream_to_path) {
    FILE *f = fopen(o->name, "w");
    if (!f || !write_all(f, o->buffer, o->size)) {
      cli_error("cannot write %s: %s", o->name, strerror(errno));
      ok = 0;
    }
    if (f && fclose(f) != 0 && ok) {
      cli_error("cannot write %s: %s", o->name, strerror(errno));
      ok = 0;
    }
  } else if (o->buffer || o->size) {
    if (!write_all(stdout, o->buffer, o->size)) {
      cli_error("cannot write to standard output: %s", strerror(errno));
      ok = 0;
    }
  }
  free(o->temp_path);
  o->temp_path = NULL;
  output_discard(o);
  return ok;
}

void output_discard(output_file *o) {
  if (o->f) {
    fclose(o->f);
    o->f = NULL;
  }
  if (o->temp_path) {
    unregister_temp(o->temp_path);
    unlink(o->temp_path);
    free(o->temp_path);
    o->temp_path = NULL;
  }
  free(o->destination);
  o->destination = NULL;
  free(o->buffer);
  o->buffer = NULL;
  o->size = 0;
}
