// sandbox/pipe_codec: what a child writes comes back as written, and a cut-off or lying stream
// is refused instead of read past its end.
#include <sandbox/pipe_codec.hpp>

#include <gtest/gtest.h>

#include <signal.h>
#include <unistd.h>

#include <cstdint>
#include <string>

using acdsandbox::PipeReader;
using acdsandbox::PipeWriter;

TEST(PipeCodec, ValuesAndTextsRoundTrip) {
  PipeWriter w;
  w.put(std::int32_t{-7});
  w.put(std::uint64_t{1} << 40);
  const double xyz[3] = {0.5, -1.25, 3e300};
  w.put(xyz);
  w.text("a name");
  w.text("");
  PipeReader r(w.data());
  std::int32_t i = 0;
  std::uint64_t u = 0;
  double back[3] = {};
  std::string a = "x", b = "x";
  ASSERT_TRUE(r.get(i) && r.get(u) && r.get(back) && r.text(a) && r.text(b));
  EXPECT_EQ(i, -7);
  EXPECT_EQ(u, std::uint64_t{1} << 40);
  EXPECT_EQ(back[0], 0.5);
  EXPECT_EQ(back[1], -1.25);
  EXPECT_EQ(back[2], 3e300);
  EXPECT_EQ(a, "a name");
  EXPECT_EQ(b, "");
  EXPECT_EQ(r.left(), 0u);
  EXPECT_FALSE(r.get(i));
}

TEST(PipeCodec, ATruncatedStreamIsRefused) {
  PipeWriter w;
  w.text("twelve bytes");
  const std::string cut = w.data().substr(0, w.data().size() - 1);
  PipeReader r(cut);
  std::string s;
  EXPECT_FALSE(r.text(s));
  std::uint64_t partial = 0;
  PipeReader shortRead(std::string_view(cut).substr(0, 3));
  EXPECT_FALSE(shortRead.get(partial));
  EXPECT_EQ(shortRead.left(), 3u);  // nothing consumed
}

TEST(PipeCodec, FitsGuardsCountsReadFromThePipe) {
  PipeWriter w;
  w.put(std::uint64_t{1000000000});  // a count the bytes that follow cannot hold
  w.put(1.0);
  PipeReader r(w.data());
  std::uint64_t n = 0;
  ASSERT_TRUE(r.get(n));
  EXPECT_FALSE(r.fits(n, sizeof(double)));
  EXPECT_TRUE(r.fits(1, sizeof(double)));
}

TEST(PipeCodec, WriteAllSendsEverythingThroughAPipe) {
  int fds[2];
  ASSERT_EQ(::pipe(fds), 0);
  const std::string bytes(10000, 'z');
  EXPECT_TRUE(acdsandbox::writeAll(fds[1], bytes));
  ::close(fds[1]);
  std::string got;
  char chunk[4096];
  for (ssize_t n; (n = ::read(fds[0], chunk, sizeof chunk)) > 0;) got.append(chunk, static_cast<std::size_t>(n));
  ::close(fds[0]);
  EXPECT_EQ(got, bytes);
  int closed[2];
  ASSERT_EQ(::pipe(closed), 0);
  ::close(closed[0]);
  ::signal(SIGPIPE, SIG_IGN);
  EXPECT_FALSE(acdsandbox::writeAll(closed[1], "nobody reads"));
  ::close(closed[1]);
}
