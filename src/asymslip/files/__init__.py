"""Files the tool reads and writes: safe (atomic) writing, and later the table readers/writers."""
