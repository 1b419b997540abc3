#pragma once
#include <cstddef>
#include <string>

namespace unimap::calibration {

// How ExtrinsicCalibrator compares the views of a map and when it stops.
struct CalibrationOptions {
  double neighbourhood_radius_m = 0.3;     // a return's neighbours lie within this distance (m)
  int min_neighbours = 8;                  // a neighbourhood's plane: at least this many returns seen from other
  int max_neighbours = 16;                 //   views than its centre's (below), at most this many (evenly chosen)
  int max_measured = 8;                    // its centre's view: at most this many returns measured against it
  double min_view_angle_deg = 10.0;        // neighbours come from other scans whose LiDAR was turned by at
  double min_view_distance_m = 0.5;        //   least this angle or moved by at least this distance: the same
                                           //   surface seen from another view (neighbours from nearly the same
                                           //   view share the extrinsic's error and say nothing about it)
  double planar_ratio = 0.1;               // a neighbourhood is planar when its smallest covariance
                                           // eigenvalue is at most this times the middle one
  double min_spread_ratio = 0.05;          // ... and its middle one at least this times the largest
                                           // (returns of a single line give no plane)
  std::size_t max_neighbourhoods = 5000;   // neighbourhoods measured at most (around an even subset of returns)
  double sigma_m = 0.01;                   // a return's noise across a surface (m): the sensor's range noise
  double max_plane_sigmas = 2.0;           // a plane whose returns lie farther from it than this many sigma_m
                                           //   (RMS) is not flat at this scale (an edge, a corner): not used
  double huber_sigmas = 2.0;               // distances beyond this many sigma_m are down-weighted (Huber)
  double prior_sigma_translation_m = 0.1;  // the platform's extrinsic as a weak prior: its uncertainty
  double prior_sigma_rotation_deg = 10.0;  //   per axis, which keeps directions the data leave open
  double max_correction_sigmas = 3.0;      // a correction beyond this many prior sigmas on any axis is no result:
                                           //   the views agree best far from the platform's extrinsic (e.g. a map
                                           //   folded onto one plane agrees with itself everywhere)
  double min_information_ratio = 2500.0;   // a direction is estimated when the data's information along it is
                                           //   at least this times the prior's (its sigma 1/50 of the prior's:
                                           //   0.2 deg, 2 mm); the others keep the platform's values
  int max_rounds = 5;                      // neighbourhoods chosen anew at most this often
  int max_iterations = 20;                 // Newton steps per round at most
  double tolerance_translation_m = 2e-5;   // a round's steps stop when one moves the extrinsic less than this
  double tolerance_rotation_deg = 5e-4;    //   and turns it less than this; the rounds stop when one moves it
                                           //   by less than its standard deviation on every axis

  // True when every field is in range; otherwise false with the field named in *why.
  bool IsValid(std::string* why) const;
};

}  // namespace unimap::calibration
