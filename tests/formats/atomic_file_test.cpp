#include "formats/atomic_file.h"

#include <filesystem>

#include <gtest/gtest.h>

#include "support/test_support.h"

namespace foldsketch {
namespace {

TEST(AtomicFile, FailedWriteLeavesTheOldFileAndNoTemporary) {
  const std::string folder = test::temp_folder();
  const std::string path = folder + "/out.txt";
  test::write_text(path, "old");
  EXPECT_THROW(write_file_atomically(path,
                                     [](std::ostream& out) {
                                       out << "half";
                                       throw std::runtime_error("boom");
                                     }),
               std::runtime_error);
  EXPECT_EQ(test::read_text(path), "old");
  int files = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(folder)) ++files;
  EXPECT_EQ(files, 1);
}

TEST(AtomicFile, SuccessfulWriteReplacesTheFile) {
  const std::string path = test::temp_folder() + "/out.txt";
  write_file_atomically(path, [](std::ostream& out) { out << "new"; });
  EXPECT_EQ(test::read_text(path), "new");
  const auto perms = std::filesystem::status(path).permissions();
  EXPECT_NE(perms & std::filesystem::perms::owner_read, std::filesystem::perms::none);
  EXPECT_NE(perms & std::filesystem::perms::others_read, std::filesystem::perms::none);
}

TEST(AtomicFile, MissingFolderIsAnInputError) {
  EXPECT_THROW(write_file_atomically("/nonexistent-folder/out.txt", [](std::ostream&) {}), std::runtime_error);
}

} // namespace
} // namespace foldsketch
