// A program outside the mechanist tree, built against an installed mechanist.
#include <iostream>

#include "io/load_assembly.h"
#include "kernel/assembly/assembly.h"

int main(int argc, char** argv) {
  if (argc != 2) return 2;
  const mechanist::Assembly assembly = mechanist::LoadAssembly(argv[1]);
  std::cout << "parts " << assembly.parts().size() << "\n";
  return assembly.parts().empty() ? 1 : 0;
}
