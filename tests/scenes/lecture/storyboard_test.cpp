// A storyboard as read, before any frame: each shot's title (given, or the card's first line, or the
// scene and what it compares), the lecture's size and fps, and the shots in order.
#include <catch2/catch.hpp>
#include <string>

#include "scenes/lecture/storyboard.hpp"

using vibra::scenes::parse_storyboard;

TEST_CASE("a shot's chapter title: as given, a card's first line, a formula's plain text, the scene and its comparison",
          "[lecture]") {
  const auto board = parse_storyboard("title = \"Damping\"\nsize = \"640x360\"\nfps = 25\n"
                                      "[[shot]]\ncard = \"The damped pendulum\"\n"
                                      "[[shot]]\nequation = \"u' = v \\\\\\\\ v' = -\\\\omega^2 u\"\n"
                                      "[[shot]]\ncard = \"Text\"\ntitle = \"Given\"\n"
                                      "[[shot]]\nscene = \"spring\"\n"
                                      "[[shot]]\nscene = \"spring\"\ncompare = \"scheme=rk4,centered\"\n"
                                      "[[shot]]\nscene = \"spring\"\ntitle = \"Mine\"\n",
                                      "story.toml");
  CHECK(board.title == "Damping");
  CHECK(board.width == 640);
  CHECK(board.height == 360);
  CHECK(board.fps == 25);
  REQUIRE(board.shots.size() == 6);
  CHECK(board.shots[0].title == "The damped pendulum");
  CHECK(board.shots[1].title == "u′ = v");  // a chapter title is one line: the formula's first
  CHECK(board.shots[2].title == "Given");
  CHECK(board.shots[3].title == "spring");
  CHECK(board.shots[4].title == "spring: scheme=rk4,centered");
  CHECK(board.shots[5].title == "Mine");
  for (int i = 0; i < 6; ++i) {
    INFO("shot " << i + 1);
    CHECK(board.shots[i].number == i + 1);
    CHECK(board.shots[i].is_card == (i < 3));
    CHECK(board.shots[i].scene.width == 640);
    CHECK(board.shots[i].scene.fps == 25);
  }
  // Without a title the file's name stands in.
  CHECK(parse_storyboard("[[shot]]\ncard = \"A\"\n", "lectures/week3.toml").title == "week3");
}
