// The program of the *_links targets of server/CMakeLists.txt: it does nothing; linking it
// with one whole floor of the server proves that the floor calls nothing above it.
int main() {
  return 0;
}
