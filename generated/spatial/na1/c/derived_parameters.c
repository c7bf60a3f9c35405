/* GENERATED FILE - DO NOT EDIT. C code emitted by CasADi for derived_parameters() of
 * generated/spatial/na1/ (see its model.py), plus its batched driver.
 * Regenerate with: python -m snakecg_derive.spatial --checked-in
 * spec sha256: f2554e7caf7b43e45e9fb60d8118a375db06d8dd0e711f01c5b700b16dc8d2be
 * tools: sympy 1.14.0, casadi 3.8.2, jinja2 3.1.6
 */
/* How to prefix internal symbols */
#ifdef CASADI_CODEGEN_PREFIX
  #define CASADI_NAMESPACE_CONCAT(NS, ID) _CASADI_NAMESPACE_CONCAT(NS, ID)
  #define _CASADI_NAMESPACE_CONCAT(NS, ID) NS ## ID
  #define CASADI_PREFIX(ID) CASADI_NAMESPACE_CONCAT(CODEGEN_PREFIX, ID)
#else
  #define CASADI_PREFIX(ID) snakecg_sp1_derived_parameters_ ## ID
#endif

#include <math.h>

#ifndef casadi_real
#define casadi_real double
#endif

#ifndef casadi_int
#define casadi_int long long int
#endif

/* Add prefix to internal symbols */
#define casadi_f0 CASADI_PREFIX(f0)
#define casadi_s0 CASADI_PREFIX(s0)
#define casadi_s1 CASADI_PREFIX(s1)
#define casadi_s2 CASADI_PREFIX(s2)
#define casadi_s3 CASADI_PREFIX(s3)
#define casadi_s4 CASADI_PREFIX(s4)
#define casadi_sq CASADI_PREFIX(sq)

/* Symbol visibility in DLLs */
#ifndef CASADI_SYMBOL_EXPORT
  #if defined(_WIN32) || defined(__WIN32__) || defined(__CYGWIN__)
    #if defined(STATIC_LINKED)
      #define CASADI_SYMBOL_EXPORT
    #else
      #define CASADI_SYMBOL_EXPORT __declspec(dllexport)
    #endif
  #elif defined(__GNUC__) && defined(GCC_HASCLASSVISIBILITY)
    #define CASADI_SYMBOL_EXPORT __attribute__ ((visibility ("default")))
  #else
    #define CASADI_SYMBOL_EXPORT
  #endif
#endif

casadi_real casadi_sq(casadi_real x) { return x*x;}

/* Configuration this file was compiled with */
CASADI_SYMBOL_EXPORT void snakecg_sp1_derived_parameters_casadi_version(int* major, int* minor, int* patch) {
  *major = 3;
  *minor = 8;
  *patch = 2;
}
CASADI_SYMBOL_EXPORT int snakecg_sp1_derived_parameters_casadi_int_size(void) { return (int) sizeof(casadi_int); }
CASADI_SYMBOL_EXPORT int snakecg_sp1_derived_parameters_casadi_real_size(void) { return (int) sizeof(casadi_real); }

static const casadi_int casadi_s0[3] = {2, 1, 1};
static const casadi_int casadi_s1[3] = {6, 1, 1};
static const casadi_int casadi_s2[3] = {12, 1, 1};
static const casadi_int casadi_s3[3] = {3, 1, 1};
static const casadi_int casadi_s4[3] = {71, 1, 1};

/* snakecg_sp1_derived_parameters:(link_mass[2],link_com[6],link_inertia[12],joint_xyz[3],joint_rpy[3],joint_axis[3],gravity[3])->(K[71]) */
static int casadi_f0(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem) {
  casadi_real a00, a01, a02, a03, a04, a05, a06, a07, a08, a09, a10, a11;
  casadi_real a12, a13, a14, a15, a16, a17, a18, a19, a20, a21, a22, a23;
  casadi_real a24, a25, a26, a27, a28, a29, a30, a31, a32, a33, a34, a35;
  casadi_real a36, a37, a38, a39, a40, a41, a42, a43;
  a00=arg[0]? arg[0][0] : 0;
  if (res[0]!=0) res[0][0]=a00;
  a00=arg[0]? arg[0][1] : 0;
  if (res[0]!=0) res[0][1]=a00;
  a00=arg[1]? arg[1][0] : 0;
  if (res[0]!=0) res[0][2]=a00;
  a01=arg[1]? arg[1][1] : 0;
  if (res[0]!=0) res[0][3]=a01;
  a02=arg[1]? arg[1][2] : 0;
  if (res[0]!=0) res[0][4]=a02;
  a03=arg[1]? arg[1][3] : 0;
  if (res[0]!=0) res[0][5]=a03;
  a04=arg[1]? arg[1][4] : 0;
  if (res[0]!=0) res[0][6]=a04;
  a05=arg[1]? arg[1][5] : 0;
  if (res[0]!=0) res[0][7]=a05;
  a06=arg[2]? arg[2][0] : 0;
  if (res[0]!=0) res[0][8]=a06;
  a07=arg[2]? arg[2][1] : 0;
  if (res[0]!=0) res[0][9]=a07;
  a08=arg[2]? arg[2][2] : 0;
  if (res[0]!=0) res[0][10]=a08;
  a09=arg[2]? arg[2][3] : 0;
  if (res[0]!=0) res[0][11]=a09;
  a10=arg[2]? arg[2][4] : 0;
  if (res[0]!=0) res[0][12]=a10;
  a11=arg[2]? arg[2][5] : 0;
  if (res[0]!=0) res[0][13]=a11;
  a12=arg[2]? arg[2][6] : 0;
  if (res[0]!=0) res[0][14]=a12;
  a13=arg[2]? arg[2][7] : 0;
  if (res[0]!=0) res[0][15]=a13;
  a14=arg[2]? arg[2][8] : 0;
  if (res[0]!=0) res[0][16]=a14;
  a15=arg[2]? arg[2][9] : 0;
  if (res[0]!=0) res[0][17]=a15;
  a16=arg[2]? arg[2][10] : 0;
  if (res[0]!=0) res[0][18]=a16;
  a17=arg[2]? arg[2][11] : 0;
  if (res[0]!=0) res[0][19]=a17;
  a18=arg[3]? arg[3][0] : 0;
  if (res[0]!=0) res[0][20]=a18;
  a19=arg[3]? arg[3][1] : 0;
  if (res[0]!=0) res[0][21]=a19;
  a20=arg[3]? arg[3][2] : 0;
  if (res[0]!=0) res[0][22]=a20;
  a21=arg[4]? arg[4][0] : 0;
  if (res[0]!=0) res[0][23]=a21;
  a22=arg[4]? arg[4][1] : 0;
  if (res[0]!=0) res[0][24]=a22;
  a23=arg[4]? arg[4][2] : 0;
  if (res[0]!=0) res[0][25]=a23;
  a24=arg[5]? arg[5][0] : 0;
  if (res[0]!=0) res[0][26]=a24;
  a25=arg[5]? arg[5][1] : 0;
  if (res[0]!=0) res[0][27]=a25;
  a26=arg[5]? arg[5][2] : 0;
  if (res[0]!=0) res[0][28]=a26;
  a27=arg[6]? arg[6][0] : 0;
  if (res[0]!=0) res[0][29]=a27;
  a27=arg[6]? arg[6][1] : 0;
  if (res[0]!=0) res[0][30]=a27;
  a27=arg[6]? arg[6][2] : 0;
  if (res[0]!=0) res[0][31]=a27;
  a27=0.;
  a28=casadi_sq(a24);
  a29=casadi_sq(a25);
  a28=(a28+a29);
  a29=casadi_sq(a26);
  a28=(a28+a29);
  a29=-5.0000000000000000e-01;
  a28=pow(a28,a29);
  a26=(a26*a28);
  a29=(a27<=a26);
  a30=1.;
  a24=(a24*a28);
  a31=casadi_sq(a24);
  a32=(a30+a26);
  a33=(a31/a32);
  a33=(a30-a33);
  a33=(a29?a33:0);
  a34=(!a29);
  a35=(a30-a26);
  a31=(a31/a35);
  a31=(a30-a31);
  a31=(a34?a31:0);
  a33=(a33+a31);
  a31=5.0000000000000000e-01;
  a36=casadi_sq(a33);
  a36=(a12*a36);
  a25=(a25*a28);
  a28=(a24*a25);
  a37=(a28/a32);
  a37=(-a37);
  a37=(a29?a37:0);
  a28=(a28/a35);
  a38=(-a28);
  a38=(a34?a38:0);
  a38=(a37+a38);
  a39=casadi_sq(a38);
  a39=(a13*a39);
  a36=(a36+a39);
  a39=(-a24);
  a39=(a29?a39:0);
  a40=(a34?a24:0);
  a39=(a39+a40);
  a40=casadi_sq(a39);
  a40=(a14*a40);
  a36=(a36+a40);
  a40=-2.;
  a41=(a40*a15);
  a28=(a34?a28:0);
  a37=(a37+a28);
  a41=(a41*a37);
  a28=casadi_sq(a25);
  a32=(a28/a32);
  a32=(a30-a32);
  a29=(a29?a32:0);
  a35=(a28/a35);
  a35=(a35-a30);
  a34=(a34?a35:0);
  a29=(a29+a34);
  a41=(a41*a29);
  a36=(a36+a41);
  a41=(2.*a15);
  a34=(a41*a33);
  a35=(a34*a38);
  a36=(a36+a35);
  a35=(2.*a16);
  a32=(a35*a33);
  a32=(a32*a39);
  a36=(a36+a32);
  a35=(a35*a37);
  a32=(a35*a25);
  a36=(a36+a32);
  a32=(2.*a17);
  a42=(a32*a38);
  a42=(a42*a39);
  a36=(a36+a42);
  a32=(a32*a29);
  a42=(a32*a25);
  a36=(a36+a42);
  a42=casadi_sq(a37);
  a42=(a12*a42);
  a36=(a36-a42);
  a42=casadi_sq(a29);
  a42=(a13*a42);
  a36=(a36-a42);
  a28=(a14*a28);
  a36=(a36-a28);
  a28=casadi_sq(a36);
  a42=(a40*a16);
  a42=(a42*a33);
  a42=(a42*a25);
  a43=(a40*a17);
  a43=(a43*a38);
  a43=(a43*a25);
  a42=(a42+a43);
  a40=(a40*a14);
  a40=(a40*a39);
  a40=(a40*a25);
  a42=(a42+a40);
  a40=(2.*a12);
  a40=(a40*a33);
  a40=(a40*a37);
  a42=(a42+a40);
  a34=(a34*a29);
  a42=(a42+a34);
  a41=(a41*a37);
  a41=(a41*a38);
  a42=(a42+a41);
  a35=(a35*a39);
  a42=(a42+a35);
  a35=(2.*a13);
  a35=(a35*a38);
  a35=(a35*a29);
  a42=(a42+a35);
  a32=(a32*a39);
  a42=(a42+a32);
  a32=casadi_sq(a42);
  a28=(a28+a32);
  a28=sqrt(a28);
  a32=(a27<a28);
  a27=(a27<=a36);
  a35=(a27?a36:0);
  a41=(!a27);
  a36=(-a36);
  a36=(a41?a36:0);
  a35=(a35+a36);
  a35=(a35/a28);
  a35=(a32?a35:0);
  a36=(!a32);
  a36=(a36?a30:0);
  a35=(a35+a36);
  a35=(a31*a35);
  a35=(a31+a35);
  a35=sqrt(a35);
  a36=(a33*a35);
  a27=(a27?a42:0);
  a42=(-a42);
  a41=(a41?a42:0);
  a27=(a27+a41);
  a27=(a27/a28);
  a31=(a31*a27);
  a31=(a31/a35);
  a27=(a37*a31);
  a27=(a32?a27:0);
  a36=(a36+a27);
  if (res[0]!=0) res[0][32]=a36;
  a27=(a38*a35);
  a28=(a29*a31);
  a28=(a32?a28:0);
  a27=(a27+a28);
  if (res[0]!=0) res[0][33]=a27;
  a28=(a39*a35);
  a41=(a25*a31);
  a41=(a32?a41:0);
  a28=(a28-a41);
  if (res[0]!=0) res[0][34]=a28;
  a37=(a37*a35);
  a33=(a33*a31);
  a33=(a32?a33:0);
  a37=(a37-a33);
  if (res[0]!=0) res[0][35]=a37;
  a29=(a29*a35);
  a38=(a38*a31);
  a38=(a32?a38:0);
  a29=(a29-a38);
  if (res[0]!=0) res[0][36]=a29;
  a39=(a39*a31);
  a32=(a32?a39:0);
  a35=(a25*a35);
  a32=(a32+a35);
  a35=(-a32);
  if (res[0]!=0) res[0][37]=a35;
  if (res[0]!=0) res[0][38]=a24;
  if (res[0]!=0) res[0][39]=a25;
  if (res[0]!=0) res[0][40]=a26;
  a35=cos(a22);
  a39=cos(a23);
  a31=(a35*a39);
  a38=(a31*a36);
  a22=sin(a22);
  a33=(a39*a22);
  a41=sin(a21);
  a33=(a33*a41);
  a21=cos(a21);
  a23=sin(a23);
  a42=(a21*a23);
  a33=(a33-a42);
  a42=(a33*a27);
  a38=(a38+a42);
  a42=(a41*a23);
  a30=(a21*a39);
  a34=(a30*a22);
  a42=(a42+a34);
  a34=(a42*a28);
  a38=(a38+a34);
  if (res[0]!=0) res[0][41]=a38;
  a38=(a35*a23);
  a34=(a38*a36);
  a40=(a22*a41);
  a40=(a40*a23);
  a30=(a30+a40);
  a40=(a30*a27);
  a34=(a34+a40);
  a40=(a21*a22);
  a40=(a40*a23);
  a39=(a39*a41);
  a40=(a40-a39);
  a39=(a40*a28);
  a34=(a34+a39);
  if (res[0]!=0) res[0][42]=a34;
  a41=(a35*a41);
  a34=(a41*a27);
  a39=(a22*a36);
  a34=(a34-a39);
  a35=(a35*a21);
  a21=(a35*a28);
  a34=(a34+a21);
  if (res[0]!=0) res[0][43]=a34;
  a34=(a31*a37);
  a21=(a33*a29);
  a34=(a34+a21);
  a21=(a42*a32);
  a34=(a34-a21);
  if (res[0]!=0) res[0][44]=a34;
  a34=(a38*a37);
  a21=(a30*a29);
  a34=(a34+a21);
  a21=(a40*a32);
  a34=(a34-a21);
  if (res[0]!=0) res[0][45]=a34;
  a34=(a41*a29);
  a21=(a22*a37);
  a34=(a34-a21);
  a21=(a35*a32);
  a34=(a34-a21);
  if (res[0]!=0) res[0][46]=a34;
  a31=(a31*a24);
  a33=(a33*a25);
  a31=(a31+a33);
  a42=(a42*a26);
  a31=(a31+a42);
  if (res[0]!=0) res[0][47]=a31;
  a38=(a38*a24);
  a30=(a30*a25);
  a38=(a38+a30);
  a40=(a40*a26);
  a38=(a38+a40);
  if (res[0]!=0) res[0][48]=a38;
  a41=(a41*a25);
  a22=(a22*a24);
  a41=(a41-a22);
  a35=(a35*a26);
  a41=(a41+a35);
  if (res[0]!=0) res[0][49]=a41;
  if (res[0]!=0) res[0][50]=a18;
  if (res[0]!=0) res[0][51]=a19;
  if (res[0]!=0) res[0][52]=a20;
  if (res[0]!=0) res[0][53]=a00;
  if (res[0]!=0) res[0][54]=a01;
  if (res[0]!=0) res[0][55]=a02;
  a02=(a36*a03);
  a01=(a27*a04);
  a02=(a02+a01);
  a01=(a28*a05);
  a02=(a02+a01);
  if (res[0]!=0) res[0][56]=a02;
  a02=(a37*a03);
  a01=(a29*a04);
  a02=(a02+a01);
  a01=(a32*a05);
  a02=(a02-a01);
  if (res[0]!=0) res[0][57]=a02;
  a03=(a24*a03);
  a04=(a25*a04);
  a03=(a03+a04);
  a05=(a26*a05);
  a03=(a03+a05);
  if (res[0]!=0) res[0][58]=a03;
  if (res[0]!=0) res[0][59]=a06;
  if (res[0]!=0) res[0][60]=a07;
  if (res[0]!=0) res[0][61]=a08;
  if (res[0]!=0) res[0][62]=a09;
  if (res[0]!=0) res[0][63]=a10;
  if (res[0]!=0) res[0][64]=a11;
  a11=(a12*a36);
  a10=(a15*a27);
  a11=(a11+a10);
  a10=(a16*a28);
  a11=(a11+a10);
  a10=(a36*a11);
  a09=(a15*a36);
  a08=(a13*a27);
  a09=(a09+a08);
  a08=(a17*a28);
  a09=(a09+a08);
  a08=(a27*a09);
  a10=(a10+a08);
  a36=(a16*a36);
  a27=(a17*a27);
  a36=(a36+a27);
  a27=(a14*a28);
  a36=(a36+a27);
  a28=(a28*a36);
  a10=(a10+a28);
  if (res[0]!=0) res[0][65]=a10;
  a10=(a12*a37);
  a28=(a15*a29);
  a10=(a10+a28);
  a28=(a16*a32);
  a10=(a10-a28);
  a28=(a37*a10);
  a27=(a15*a37);
  a08=(a13*a29);
  a27=(a27+a08);
  a08=(a17*a32);
  a27=(a27-a08);
  a08=(a29*a27);
  a28=(a28+a08);
  a08=(a16*a37);
  a07=(a17*a29);
  a08=(a08+a07);
  a07=(a14*a32);
  a08=(a08-a07);
  a07=(a32*a08);
  a28=(a28-a07);
  if (res[0]!=0) res[0][66]=a28;
  a12=(a12*a24);
  a28=(a15*a25);
  a12=(a12+a28);
  a28=(a16*a26);
  a12=(a12+a28);
  a12=(a24*a12);
  a15=(a15*a24);
  a13=(a13*a25);
  a15=(a15+a13);
  a13=(a17*a26);
  a15=(a15+a13);
  a15=(a25*a15);
  a12=(a12+a15);
  a16=(a16*a24);
  a17=(a17*a25);
  a16=(a16+a17);
  a14=(a14*a26);
  a16=(a16+a14);
  a16=(a26*a16);
  a12=(a12+a16);
  if (res[0]!=0) res[0][67]=a12;
  a37=(a37*a11);
  a29=(a29*a09);
  a37=(a37+a29);
  a32=(a32*a36);
  a37=(a37-a32);
  if (res[0]!=0) res[0][68]=a37;
  a11=(a24*a11);
  a09=(a25*a09);
  a11=(a11+a09);
  a36=(a26*a36);
  a11=(a11+a36);
  if (res[0]!=0) res[0][69]=a11;
  a24=(a24*a10);
  a25=(a25*a27);
  a24=(a24+a25);
  a26=(a26*a08);
  a24=(a24+a26);
  if (res[0]!=0) res[0][70]=a24;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_sp1_derived_parameters(const casadi_real** arg, casadi_real** res, casadi_int* iw, casadi_real* w, int mem){
  return casadi_f0(arg, res, iw, w, mem);
}

CASADI_SYMBOL_EXPORT int snakecg_sp1_derived_parameters_checkout(void) {
  return 0;
}

CASADI_SYMBOL_EXPORT void snakecg_sp1_derived_parameters_release(int mem) {
}

CASADI_SYMBOL_EXPORT void snakecg_sp1_derived_parameters_incref(void) {
}

CASADI_SYMBOL_EXPORT void snakecg_sp1_derived_parameters_decref(void) {
}

CASADI_SYMBOL_EXPORT casadi_int snakecg_sp1_derived_parameters_n_in(void) { return 7;}

CASADI_SYMBOL_EXPORT casadi_int snakecg_sp1_derived_parameters_n_out(void) { return 1;}

CASADI_SYMBOL_EXPORT casadi_real snakecg_sp1_derived_parameters_default_in(casadi_int i) {
  switch (i) {
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_sp1_derived_parameters_name_in(casadi_int i) {
  switch (i) {
    case 0: return "link_mass";
    case 1: return "link_com";
    case 2: return "link_inertia";
    case 3: return "joint_xyz";
    case 4: return "joint_rpy";
    case 5: return "joint_axis";
    case 6: return "gravity";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const char* snakecg_sp1_derived_parameters_name_out(casadi_int i) {
  switch (i) {
    case 0: return "K";
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_sp1_derived_parameters_sparsity_in(casadi_int i) {
  switch (i) {
    case 0: return casadi_s0;
    case 1: return casadi_s1;
    case 2: return casadi_s2;
    case 3: return casadi_s3;
    case 4: return casadi_s3;
    case 5: return casadi_s3;
    case 6: return casadi_s3;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT const casadi_int* snakecg_sp1_derived_parameters_sparsity_out(casadi_int i) {
  switch (i) {
    case 0: return casadi_s4;
    default: return 0;
  }
}

CASADI_SYMBOL_EXPORT int snakecg_sp1_derived_parameters_work(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 7;
  if (sz_res) *sz_res = 1;
  if (sz_iw) *sz_iw = 0;
  if (sz_w) *sz_w = 0;
  return 0;
}

CASADI_SYMBOL_EXPORT int snakecg_sp1_derived_parameters_work_bytes(casadi_int *sz_arg, casadi_int* sz_res, casadi_int *sz_iw, casadi_int *sz_w) {
  if (sz_arg) *sz_arg = 7*sizeof(const casadi_real*);
  if (sz_res) *sz_res = 1*sizeof(casadi_real*);
  if (sz_iw) *sz_iw = 0*sizeof(casadi_int);
  if (sz_w) *sz_w = 0*sizeof(casadi_real);
  return 0;
}



/* ------------------------------------------------------------------------------------------
 * GENERATED FILE - DO NOT EDIT. Batched drivers rendered from derive/templates/batch.c.j2.
 * snakecg's counterpart of CasADi's Function.map(n, "serial"): one loop in C over n samples,
 * reading inputs in place (input k of sample i at arg[k] + i * stride[k]; stride 0 broadcasts)
 * and writing dense column-major outputs contiguously (output k of sample i at
 * res[k] + i * nnz_out(k)). Returns 0 on success, the failing sample + 1 otherwise, -1 when out of memory.
 * ---------------------------------------------------------------------------------------- */
#include <stdlib.h>

CASADI_SYMBOL_EXPORT int snakecg_sp1_batch_derived_parameters(casadi_int n, const casadi_real** arg,
    const casadi_int* stride, casadi_real** res) {
  const casadi_real* a[7];
  casadi_real* r[1];
  casadi_int* iw = (casadi_int*) malloc(sizeof(casadi_int) * 1);
  casadi_real* w = (casadi_real*) malloc(sizeof(casadi_real) * 45);
  casadi_int i, k;
  int status = 0;
  if (!iw || !w) { free(iw); free(w); return -1; }
  for (k = 0; k < 7; ++k) a[k] = 0;
  for (k = 0; k < 1; ++k) r[k] = 0;
  for (i = 0; i < n; ++i) {
    a[0] = arg[0] + i * stride[0];
    a[1] = arg[1] + i * stride[1];
    a[2] = arg[2] + i * stride[2];
    a[3] = arg[3] + i * stride[3];
    a[4] = arg[4] + i * stride[4];
    a[5] = arg[5] + i * stride[5];
    a[6] = arg[6] + i * stride[6];
    r[0] = res[0] + i * 71;
    if (snakecg_sp1_derived_parameters(a, r, iw, w, 0)) { status = (int) (i + 1); break; }
  }
  free(iw);
  free(w);
  return status;
}
