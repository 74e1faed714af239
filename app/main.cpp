// m3055: command-line entry point (render; more subcommands follow).
int main() { return 0; }
