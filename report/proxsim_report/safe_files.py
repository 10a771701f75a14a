"""Files the report writes, under the C++ writers' rules (src/core/atomic_file.h):
never through a symbolic link, and whole or not at all.

The folder is opened with O_NOFOLLOW; NAME.tmp is created with O_CREAT | O_EXCL |
O_NOFOLLOW relative to it (a link planted under that name is refused; a regular
file left by a killed report is replaced) and renamed over NAME, which replaces
a link there rather than writing through it. A device, FIFO, socket or folder
under NAME is refused.
"""
import io
import os
import stat


class UnsafeFileError(OSError):
    """A file the report will not write: a link or a special file in its place."""


def write_bytes(path, data):
    folder, name = os.path.split(path)
    try:
        dir_fd = os.open(folder or ".", os.O_RDONLY | os.O_DIRECTORY | os.O_NOFOLLOW | os.O_CLOEXEC)
    except OSError as e:
        raise UnsafeFileError(f"{path}: its folder is a symbolic link or cannot be opened ({e.strerror}); "
                              "the report never writes through a link") from None
    tmp = name + ".tmp"
    try:
        try:
            mode = os.stat(name, dir_fd=dir_fd, follow_symlinks=False).st_mode
            if not (stat.S_ISREG(mode) or stat.S_ISLNK(mode)):
                raise UnsafeFileError(f"{path}: not a regular file; the report never replaces one")
        except FileNotFoundError:
            pass
        flags = os.O_WRONLY | os.O_CREAT | os.O_EXCL | os.O_NOFOLLOW | os.O_CLOEXEC
        try:
            fd = os.open(tmp, flags, 0o644, dir_fd=dir_fd)
        except FileExistsError:
            if not stat.S_ISREG(os.stat(tmp, dir_fd=dir_fd, follow_symlinks=False).st_mode):
                raise UnsafeFileError(f"{path}.tmp: a symbolic link or not a regular file; "
                                      "the report never writes through one (remove it)") from None
            os.unlink(tmp, dir_fd=dir_fd)  # left by a killed report
            fd = os.open(tmp, flags, 0o644, dir_fd=dir_fd)
        try:
            with os.fdopen(fd, "wb") as f:
                f.write(data)
            os.replace(tmp, name, src_dir_fd=dir_fd, dst_dir_fd=dir_fd)
        except BaseException:
            try:
                os.unlink(tmp, dir_fd=dir_fd)
            except OSError:
                pass
            raise
    finally:
        os.close(dir_fd)


def write_text(path, text):
    write_bytes(path, text.encode("utf-8"))


def save_figure(fig, path, **kwargs):
    """fig.savefig(path), through write_bytes; the format from the path's extension."""
    buffer = io.BytesIO()
    fig.savefig(buffer, format=os.path.splitext(path)[1][1:], **kwargs)
    write_bytes(path, buffer.getvalue())
