// The tables analyze prints: text columns flush left, numbers flush right, reals to 4 digits, NaN empty; CSV exact.
#include <catch2/catch.hpp>
#include <cmath>

#include "jobs/table.hpp"

using vibra::app::Table;

TEST_CASE("an aligned table puts text flush left and numbers flush right, two spaces apart", "[table]") {
  Table table({"scheme", "n", "error"});
  table.add_row({std::string("rk4"), 10LL, 1.23456e-5});
  table.add_row({std::string("forward-euler"), 1000LL, 0.5});
  table.add_row({std::string("centered"), 7LL, NAN});
  CHECK(table.aligned() ==
        "scheme            n      error\n"
        "rk4              10  1.235e-05\n"
        "forward-euler  1000        0.5\n"
        "centered          7\n");
  // CSV: every real exactly, NaN an empty cell.
  CHECK(table.csv() == "scheme,n,error\nrk4,10,1.23456e-05\nforward-euler,1000,0.5\ncentered,7,\n");
}
