#include "sundials/nvector_compiled.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "dlpverify/errors.hpp"
#include "harness/compensated_sum.hpp"

namespace dlpverify::sun {

namespace {

// The content of our vector: the serial vector's, whether it owns its data, and its shape
// (fields == 0: none given, a flat vector).
struct Content {
  sunindextype length = 0;
  double* data = nullptr;
  bool owns_data = false;
  sunindextype members = 0;
  int fields = 0;
};

Content* content(N_Vector v) { return static_cast<Content*>(v->content); }

// N_VGetArrayPointer and N_VGetLength go through the table; inside the kernels we read directly.
double* data_of(N_Vector v) { return content(v)->data; }
sunindextype length_of(N_Vector v) { return content(v)->length; }

N_Vector_ID vector_id(N_Vector) { return SUNDIALS_NVEC_CUSTOM; }
sunindextype length(N_Vector v) { return length_of(v); }
double* array_pointer(N_Vector v) { return data_of(v); }
void set_array_pointer(double* data, N_Vector v) {
  if (content(v)->owns_data) std::free(content(v)->data);
  content(v)->data = data;
  content(v)->owns_data = false;
}
void space(N_Vector v, sunindextype* real_words, sunindextype* integer_words) {
  *real_words = length_of(v);
  *integer_words = 1;
}
void destroy(N_Vector v) {
  if (v == nullptr) return;
  if (v->content != nullptr) {
    if (content(v)->owns_data) std::free(content(v)->data);
    delete content(v);
    v->content = nullptr;
  }
  N_VFreeEmpty(v);
}

template <bool Threaded>
N_Vector empty_vector(sunindextype n, SUNContext context);

template <bool Threaded>
N_Vector clone_empty(N_Vector w) {
  N_Vector v = empty_vector<Threaded>(length_of(w), w->sunctx);
  if (v != nullptr) {
    content(v)->members = content(w)->members;
    content(v)->fields = content(w)->fields;
  }
  return v;
}
template <bool Threaded>
N_Vector clone(N_Vector w) {
  N_Vector v = clone_empty<Threaded>(w);
  if (v == nullptr) return nullptr;
  const sunindextype n = length_of(w);
  content(v)->data = n > 0 ? static_cast<double*>(std::malloc(sizeof(double) * static_cast<std::size_t>(n))) : nullptr;
  if (n > 0 && content(v)->data == nullptr) {
    destroy(v);
    return nullptr;
  }
  content(v)->owns_data = true;
  return v;
}

// ---- compiled vector operations -------------------------------------------------------------
//
// Each loop is element-wise (z may alias x or y) and mirrors the serial N_Vector of SUNDIALS 6.4.1
// (src/nvector/serial/nvector_serial.c). Threaded<true> splits loops over the OpenMP threads once
// the vector is long enough for that to pay; its sums go by fixed pieces — (field, block) partials
// for a shaped vector (vector_sum), chunks of entries for an unshaped one (ordered_sum) — so the
// thread count changes no bit.


constexpr sunindextype kThreadedLength = 4096;
constexpr sunindextype kSumBlock = dlpverify::kSumBlock;  // members per block of a shaped vector's sums

double total_in_order(const std::vector<double>& partials) {
  if (partials.size() == 1) return partials.front();
  double total = 0.0;
  for (double partial : partials) total += partial;
  return total;
}

template <bool Threaded>
struct Ops {
  static bool threaded(sunindextype n) { return Threaded && n >= kThreadedLength; }

  // z[i] = value(i) for i < n (z may be an input: each entry reads its own inputs first): over
  // the threads when Threaded and the vector is long enough, else one vectorised loop. Not an
  // `omp parallel … if (false)`: that still asks the OpenMP runtime for a team of one on every
  // call, which for the reference's short per-block vectors (solved on the threads already)
  // cost as much as the loop.
  template <class Value>
  static void each(sunindextype n, double* z, const Value& value) {
    if constexpr (Threaded) {
      if (threaded(n)) {
#pragma omp parallel for simd schedule(static)
        for (sunindextype i = 0; i < n; ++i) z[i] = value(i);
        return;
      }
    }
#pragma omp simd
    for (sunindextype i = 0; i < n; ++i) z[i] = value(i);
  }

  // Σ_{first ≤ i < last} term(i) in kPartials running sums, entry i into sum (i − first) mod
  // kPartials, the sums then added pairwise. Several independent sums because one is bound by the
  // add's latency (CVODE's error norms were a seventh of its time); a fixed assignment, not an
  // `omp simd` reduction, so the bits do not depend on the vector width either.
  static constexpr int kPartials = 16;
  template <class Term>
  static double local_sum(sunindextype first, sunindextype last, const Term& term) {
    double partial[kPartials] = {};
    sunindextype i = first;
    for (; i + kPartials <= last; i += kPartials)
#pragma omp simd
      for (int k = 0; k < kPartials; ++k) partial[k] += term(i + k);
    for (int k = 0; i < last; ++i, ++k) partial[k] += term(i);
    for (int width = kPartials / 2; width > 0; width /= 2)
      for (int k = 0; k < width; ++k) partial[k] += partial[k + width];
    return partial[0];
  }
  // Σ_{i < n} term(i). Threaded, in fixed chunks of kThreadedLength entries whose sums are added
  // in chunk order: the threads share out whole chunks, so the bits do not depend on how many
  // threads there are. (A reduction over the threads would: CVODE's error norms, and so its
  // steps, would change with --threads.)
  template <class Term>
  static double ordered_sum(sunindextype n, const Term& term) {
    if (!threaded(n)) return local_sum(0, n, term);
    const sunindextype chunks = (n + kThreadedLength - 1) / kThreadedLength;
    std::vector<double> partials(static_cast<std::size_t>(chunks));
#pragma omp parallel for schedule(static)
    for (sunindextype c = 0; c < chunks; ++c)
      partials[static_cast<std::size_t>(c)] =
          local_sum(c * kThreadedLength, std::min(n, (c + 1) * kThreadedLength), term);
    double total = 0.0;
    for (double partial : partials) total += partial;
    return total;
  }

  // z = a x + b y. CVODE's Adams predictor is q(q+1)/2 calls with a = b = 1 per step, a third of
  // the reference's time: that case (and a = 1 or b = 1) skips the products, which are exact
  // there (1·x = x), so the bits are those of the general loop.
  static void linear_sum(double a, N_Vector x, double b, N_Vector y, N_Vector z) {
    const sunindextype n = length_of(x);
    const double* xd = data_of(x);
    const double* yd = data_of(y);
    double* zd = data_of(z);
    if (a == 1.0 && b == 1.0)
      each(n, zd, [=](sunindextype i) { return xd[i] + yd[i]; });
    else if (a == 1.0)
      each(n, zd, [=](sunindextype i) { return xd[i] + b * yd[i]; });
    else if (b == 1.0)
      each(n, zd, [=](sunindextype i) { return a * xd[i] + yd[i]; });
    else
      each(n, zd, [=](sunindextype i) { return a * xd[i] + b * yd[i]; });
  }
  static void constant(double c, N_Vector z) {
    const sunindextype n = length_of(z);
    double* zd = data_of(z);
    each(n, zd, [=](sunindextype) { return c; });
  }
  static void product(N_Vector x, N_Vector y, N_Vector z) {
    const sunindextype n = length_of(x);
    const double* xd = data_of(x);
    const double* yd = data_of(y);
    double* zd = data_of(z);
    each(n, zd, [=](sunindextype i) { return xd[i] * yd[i]; });
  }
  static void divide(N_Vector x, N_Vector y, N_Vector z) {
    const sunindextype n = length_of(x);
    const double* xd = data_of(x);
    const double* yd = data_of(y);
    double* zd = data_of(z);
    each(n, zd, [=](sunindextype i) { return xd[i] / yd[i]; });
  }
  static void scale(double c, N_Vector x, N_Vector z) {
    const sunindextype n = length_of(x);
    const double* xd = data_of(x);
    double* zd = data_of(z);
    each(n, zd, [=](sunindextype i) { return c * xd[i]; });
  }
  static void absolute(N_Vector x, N_Vector z) {
    const sunindextype n = length_of(x);
    const double* xd = data_of(x);
    double* zd = data_of(z);
    each(n, zd, [=](sunindextype i) { return std::fabs(xd[i]); });
  }
  static void inverse(N_Vector x, N_Vector z) {
    const sunindextype n = length_of(x);
    const double* xd = data_of(x);
    double* zd = data_of(z);
    each(n, zd, [=](sunindextype i) { return 1.0 / xd[i]; });
  }
  static void add_constant(N_Vector x, double b, N_Vector z) {
    const sunindextype n = length_of(x);
    const double* xd = data_of(x);
    double* zd = data_of(z);
    each(n, zd, [=](sunindextype i) { return xd[i] + b; });
  }
  static void compare(double c, N_Vector x, N_Vector z) {  // z = (|x| ≥ c) ? 1 : 0
    const sunindextype n = length_of(x);
    const double* xd = data_of(x);
    double* zd = data_of(z);
    each(n, zd, [=](sunindextype i) { return std::fabs(xd[i]) >= c ? 1.0 : 0.0; });
  }
  static sunbooleantype invert_test(N_Vector x, N_Vector z) {  // z = 1/x where x ≠ 0; false if any x = 0
    const sunindextype n = length_of(x);
    const double* xd = data_of(x);
    double* zd = data_of(z);
    int zeros = 0;
    const auto invert = [=](sunindextype i) {  // 1 where x is 0 (z left as it is), else z = 1/x and 0
      if (xd[i] == 0.0) return 1;
      zd[i] = 1.0 / xd[i];
      return 0;
    };
    if (threaded(n)) {
#pragma omp parallel for schedule(static) reduction(+ : zeros)
      for (sunindextype i = 0; i < n; ++i) zeros += invert(i);
    } else {
      for (sunindextype i = 0; i < n; ++i) zeros += invert(i);
    }
    return zeros == 0 ? SUNTRUE : SUNFALSE;
  }

  // The terms of the sums: x·y, |x|, (x w)² and (x w)² where id > 0.
  static auto dot_term(N_Vector x, N_Vector y) {
    const double* xd = data_of(x);
    const double* yd = data_of(y);
    return [=](sunindextype i) { return xd[i] * yd[i]; };
  }
  static auto l1_term(N_Vector x) {
    const double* xd = data_of(x);
    return [=](sunindextype i) { return std::fabs(xd[i]); };
  }
  static auto square_term(N_Vector x, N_Vector w) {
    const double* xd = data_of(x);
    const double* wd = data_of(w);
    return [=](sunindextype i) {
      const double product = xd[i] * wd[i];
      return product * product;
    };
  }
  static auto masked_square_term(N_Vector x, N_Vector w, N_Vector id) {
    const double* xd = data_of(x);
    const double* wd = data_of(w);
    const double* idd = data_of(id);
    return [=](sunindextype i) {
      const double product = idd[i] > 0.0 ? xd[i] * wd[i] : 0.0;
      return product * product;
    };
  }

  // A shaped vector's partial sums: one local_sum per (field f, block b of kSumBlock members),
  // in the order f, then b (index f·blocks + b). Threaded, the threads share out whole partials.
  template <class Term>
  static std::vector<double> block_partials(const Content& c, const Term& term) {
    const sunindextype blocks = (c.members + kSumBlock - 1) / kSumBlock;
    const sunindextype count = blocks * c.fields;
    std::vector<double> partials(static_cast<std::size_t>(count));
    const auto partial = [&](sunindextype k) {
      const sunindextype field_start = (k / blocks) * c.members, b = k % blocks;
      partials[static_cast<std::size_t>(k)] =
          local_sum(field_start + b * kSumBlock, field_start + std::min(c.members, (b + 1) * kSumBlock), term);
    };
    if (threaded(c.length)) {
#pragma omp parallel for schedule(static)
      for (sunindextype k = 0; k < count; ++k) partial(k);
    } else {
      for (sunindextype k = 0; k < count; ++k) partial(k);
    }
    return partials;
  }
  // Σ term over the vector. Shaped (set_shape): one local_sum when the members fit in one block
  // (the CVODE reference's short vectors), else the (field, block) partials added in that order,
  // so a population split over processes at block boundaries can add the same partials in the
  // same order (docs/mpi.md). Unshaped: ordered_sum over the flat vector.
  template <class Term>
  static double vector_sum(N_Vector v, const Term& term) {
    const Content& c = *content(v);
    if (c.fields == 0) return ordered_sum(c.length, term);
    if (c.members <= kSumBlock) return local_sum(0, c.length, term);
    return total_in_order(block_partials(c, term));
  }
  // What partial_sums returns: the (field, block) partials, or with `by_block` false the one
  // local_sum over the whole vector (none for an empty one).
  template <class Term>
  static std::vector<double> partials(N_Vector v, bool by_block, const Term& term) {
    const Content& c = *content(v);
    if (by_block) return block_partials(c, term);
    if (c.length == 0) return {};
    return {local_sum(0, c.length, term)};
  }

  static double dot_product(N_Vector x, N_Vector y) { return vector_sum(x, dot_term(x, y)); }
  static double max_norm(N_Vector x) {
    const sunindextype n = length_of(x);
    const double* xd = data_of(x);
    double largest = 0.0;
    if (threaded(n)) {
#pragma omp parallel for simd schedule(static) reduction(max : largest)
      for (sunindextype i = 0; i < n; ++i) largest = std::max(largest, std::fabs(xd[i]));
    } else {
#pragma omp simd reduction(max : largest)
      for (sunindextype i = 0; i < n; ++i) largest = std::max(largest, std::fabs(xd[i]));
    }
    return largest;
  }
  static double minimum(N_Vector x) {
    const sunindextype n = length_of(x);
    const double* xd = data_of(x);
    double smallest = n > 0 ? xd[0] : SUN_BIG_REAL;
    if (threaded(n)) {
#pragma omp parallel for simd schedule(static) reduction(min : smallest)
      for (sunindextype i = 0; i < n; ++i) smallest = std::min(smallest, xd[i]);
    } else {
#pragma omp simd reduction(min : smallest)
      for (sunindextype i = 0; i < n; ++i) smallest = std::min(smallest, xd[i]);
    }
    return smallest;
  }
  static double l1_norm(N_Vector x) { return vector_sum(x, l1_term(x)); }
  static double weighted_square_sum(N_Vector x, N_Vector w) { return vector_sum(x, square_term(x, w)); }
  static double weighted_square_sum_masked(N_Vector x, N_Vector w, N_Vector id) {
    return vector_sum(x, masked_square_term(x, w, id));
  }
  static double wrms_norm(N_Vector x, N_Vector w) {
    return std::sqrt(weighted_square_sum(x, w) / static_cast<double>(length_of(x)));
  }
  static double wrms_norm_masked(N_Vector x, N_Vector w, N_Vector id) {
    return std::sqrt(weighted_square_sum_masked(x, w, id) / static_cast<double>(length_of(x)));
  }
  static double wl2_norm(N_Vector x, N_Vector w) { return std::sqrt(weighted_square_sum(x, w)); }

  // z = Σ_j c_j X_j (z may be one of the X_j: each entry reads all X_j before writing z).
  static int linear_combination(int count, double* c, N_Vector* xs, N_Vector z) {
    if (count < 1) return -1;  // SUNDIALS: SUN_ERR_ARG_OUTOFRANGE / -1
    const sunindextype n = length_of(z);
    double* zd = data_of(z);
    constexpr int kBlock = 16;  // columns summed per pass
    for (int first = 0; first < count; first += kBlock) {
      const int last = std::min(count, first + kBlock);
      const double* columns[kBlock];
      for (int j = first; j < last; ++j) columns[j - first] = data_of(xs[j]);
      const bool accumulate = first > 0;
      const auto entry = [&](sunindextype i) {
        double sum = accumulate ? zd[i] : 0.0;
        for (int j = first; j < last; ++j) sum += c[j] * columns[j - first][i];
        zd[i] = sum;
      };
      if (threaded(n)) {
#pragma omp parallel for schedule(static)
        for (sunindextype i = 0; i < n; ++i) entry(i);
      } else {
        for (sunindextype i = 0; i < n; ++i) entry(i);
      }
    }
    return 0;
  }
  // Z_j = a_j x + Y_j for j < count (CVODE's update of the whole Nordsieck history).
  static int scale_add_multi(int count, double* a, N_Vector x, N_Vector* ys, N_Vector* zs) {
    if (count < 1) return -1;
    for (int j = 0; j < count; ++j) linear_sum(a[j], x, 1.0, ys[j], zs[j]);
    return 0;
  }

  static void install(N_Vector v) {
    N_Vector_Ops ops = v->ops;
    ops->nvgetvectorid = vector_id;
    ops->nvclone = clone<Threaded>;
    ops->nvcloneempty = clone_empty<Threaded>;
    ops->nvdestroy = destroy;
    ops->nvspace = space;
    ops->nvgetarraypointer = array_pointer;
    ops->nvsetarraypointer = set_array_pointer;
    ops->nvgetlength = length;
    ops->nvlinearsum = linear_sum;
    ops->nvconst = constant;
    ops->nvprod = product;
    ops->nvdiv = divide;
    ops->nvscale = scale;
    ops->nvabs = absolute;
    ops->nvinv = inverse;
    ops->nvaddconst = add_constant;
    ops->nvdotprod = dot_product;
    ops->nvmaxnorm = max_norm;
    ops->nvwrmsnorm = wrms_norm;
    ops->nvwrmsnormmask = wrms_norm_masked;
    ops->nvmin = minimum;
    ops->nvwl2norm = wl2_norm;
    ops->nvl1norm = l1_norm;
    ops->nvcompare = compare;
    ops->nvinvtest = invert_test;
    ops->nvlinearcombination = linear_combination;
    ops->nvscaleaddmulti = scale_add_multi;
    // The local reductions (the same, for a vector on one process).
    ops->nvdotprodlocal = dot_product;
    ops->nvmaxnormlocal = max_norm;
    ops->nvminlocal = minimum;
    ops->nvl1normlocal = l1_norm;
    ops->nvinvtestlocal = invert_test;
    ops->nvwsqrsumlocal = weighted_square_sum;
    ops->nvwsqrsummasklocal = weighted_square_sum_masked;
  }
};


template <bool Threaded>
N_Vector empty_vector(sunindextype n, SUNContext context) {
  N_Vector v = N_VNewEmpty(context);
  if (v == nullptr) return nullptr;
  v->content = new Content{n, nullptr, false};
  Ops<Threaded>::install(v);
  return v;
}

}  // namespace

N_Vector new_compiled_vector(sunindextype length, bool threaded, SUNContext context) {
  N_Vector model = threaded ? empty_vector<true>(length, context) : empty_vector<false>(length, context);
  if (model == nullptr) return nullptr;
  N_Vector v = N_VClone(model);
  destroy(model);
  return v;
}

N_Vector wrap_compiled_vector(double* data, sunindextype length, bool threaded, SUNContext context) {
  N_Vector v = threaded ? empty_vector<true>(length, context) : empty_vector<false>(length, context);
  if (v != nullptr) content(v)->data = data;
  return v;
}

bool is_compiled_vector(N_Vector v) {
  return v != nullptr && (v->ops->nvlinearsum == Ops<false>::linear_sum || v->ops->nvlinearsum == Ops<true>::linear_sum);
}

void set_shape(N_Vector v, sunindextype members, int fields) {
  if (fields <= 0 || members < 0 || members * fields != length_of(v))
    throw SolverError("set_shape: " + std::to_string(members) + " members x " + std::to_string(fields) +
                      " fields do not make a vector of " + std::to_string(length_of(v)) + " entries");
  content(v)->members = members;
  content(v)->fields = fields;
}

VectorShape shape_of(N_Vector v) { return {content(v)->members, content(v)->fields}; }

namespace {

template <bool Threaded>
std::vector<double> partials_of(VectorSum sum, N_Vector x, N_Vector y, N_Vector id, bool by_block) {
  using O = Ops<Threaded>;
  switch (sum) {
    case VectorSum::dot: return O::partials(x, by_block, O::dot_term(x, y));
    case VectorSum::l1: return O::partials(x, by_block, O::l1_term(x));
    case VectorSum::weighted_squares: return O::partials(x, by_block, O::square_term(x, y));
    case VectorSum::weighted_squares_masked: return O::partials(x, by_block, O::masked_square_term(x, y, id));
  }
  return {};
}

}  // namespace

std::vector<double> partial_sums(VectorSum sum, N_Vector x, N_Vector y, N_Vector id, bool by_block) {
  return x->ops->nvlinearsum == Ops<true>::linear_sum ? partials_of<true>(sum, x, y, id, by_block)
                                                      : partials_of<false>(sum, x, y, id, by_block);
}

double ordered_total(const std::vector<double>& partials) { return total_in_order(partials); }

}  // namespace dlpverify::sun
