// Grade a labelling computed elsewhere (say, by a floating-point graph cut) on an hsx-complex/1 file: is it a
// valid BSH boundary, what is its exact energy, and is it optimal?
// Usage: grade_labelling COMPLEX.json LABELS.txt   (LABELS: one 0/1 per cell, in the complex's cell order)
#include <hsx/hsx.hpp>

#include <fstream>
#include <iostream>

int main(int argc, char** argv) {
  if (argc != 3) {
    std::cerr << "usage: grade_labelling COMPLEX.json LABELS.txt\n";
    return 2;
  }
  try {
    const hsx::Complex complex = hsx::read_complex_file(argv[1]);
    std::ifstream labels_file(argv[2]);
    hsx::bsh::Labelling labels;
    for (int label; labels_file >> label;) labels.push_back(label == 1);
    if (!labels_file.eof()) throw hsx::InputError(std::string(argv[2]) + ": labels must be 0 or 1");

    const hsx::bsh::Grade grade = hsx::grade_labelling(complex, labels);
    std::cout << "orientation-preserving " << (grade.orientation_preserving ? "yes" : "no: ")
              << grade.orientation_problem << "\n";
    std::cout << "sample-connected " << (grade.sample_connected ? "yes" : "no") << ", islands "
              << grade.islands.size() << "\n";
    for (const hsx::bsh::Component& island : grade.islands)
      std::cout << "  island on " << complex.halfspace_names[island.halfspace] << ": " << island.patches.size()
                << " patches without a sample\n";
    std::cout << "energy " << grade.energy.missing_samples << " missing, " << grade.energy.measure().decimal_string(15)
              << "; optimum " << grade.optimum.energy.missing_samples << " missing, "
              << grade.optimum.energy.measure().decimal_string(15) << "\n";
    std::cout << "versus optimum: " << hsx::to_string(grade.versus_optimum) << "\n";
    std::cout << (grade.optimal() ? "OPTIMAL" : "NOT OPTIMAL") << "\n";
    return grade.optimal() ? 0 : 3;
  } catch (const hsx::InputError& e) {
    std::cerr << "bad input: " << e.what() << "\n";
    return 2;
  }
}
