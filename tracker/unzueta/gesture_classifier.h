// The gesture and pose classifiers of Unzueta 2009 §5.2 and Table 15, from OpenCV's ml module:
// K-NN (K = 1 in the thesis) and an SVM with a cubic polynomial kernel (degree 3, gamma 0.01,
// coef0 0, C 10), trained on labelled feature vectors.
#pragma once

#include <Eigen/Core>
#include <opencv2/ml.hpp>
#include <string>
#include <vector>

#include "core/name_table.h"

namespace simcap::tracker {

enum class GestureClassifierKind { knn, svm };
inline constexpr NameTable<GestureClassifierKind, 2> kGestureClassifiers{
    {{"knn", GestureClassifierKind::knn}, {"svm", GestureClassifierKind::svm}}};

class GestureClassifier {
 public:
  explicit GestureClassifier(GestureClassifierKind kind, int k = 1) : kind_(kind), k_(k) {}
  // Every sample has the same length; at least one sample (the SVM: two labels). Throws Error.
  void train(const std::vector<Eigen::VectorXd>& samples, const std::vector<std::string>& labels);
  // The predicted label.
  std::string predict(const Eigen::VectorXd& sample) const;
  const std::vector<std::string>& labels() const { return names_; }

 private:
  GestureClassifierKind kind_;
  int k_;
  std::vector<std::string> names_;  // class index -> label, sorted
  cv::Ptr<cv::ml::StatModel> model_;
};

}  // namespace simcap::tracker
