// A solid given as a CSG expression over a scene's halfspaces: is it describable by them (Shapiro-Vossler), and
// Buchele-Crawford's halfspace CSG tree for it, verified on every cell.
// Usage: csg_tree SCENE.json "EXPRESSION"     e.g. csg_tree lens.json "(A | B) & ~C"
#include <hsx/hsx.hpp>

#include <iostream>

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: csg_tree SCENE.json EXPRESSION\n";
    return 2;
  }
  try {
    const hsx::LoadedInput in = hsx::load_input(argv[1]);
    const hsx::Complex& complex = in.complex();
    const std::vector<char> solid = hsx::solid_from_csg(complex, argv[2]);

    const hsx::csg::Describability d = hsx::csg::describability(complex, solid);
    std::cout << "describable " << (d.describable ? "yes" : "no") << " (" << d.terms << " canonical terms, "
              << d.mixed.size() << " mixed)\n";

    const hsx::csg::BhcResult tree = hsx::csg_tree(in, solid);
    if (!tree.describable) {
      std::cout << "no tree: the mixed term holds cells " << tree.witness.inside_cells.front() << " (in) and "
                << tree.witness.outside_cells.front() << " (out)\n";
      return 3;
    }
    std::cout << "tree " << hsx::csg::to_text(*tree.tree, complex.halfspace_names) << "\n";
    std::cout << "verified on every cell " << (tree.verified ? "yes" : "NO") << ", " << tree.stats.leaves
              << " leaves\n";
    return tree.verified ? 0 : 1;
  } catch (const hsx::InputError& e) {
    std::cerr << "bad input: " << e.what() << "\n";
    return 2;
  }
}
