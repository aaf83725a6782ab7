"""Work built from many runs or for the command line: the skid map, rendering a run, the CLI."""
