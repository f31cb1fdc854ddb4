//Maya ASCII 2020 scene
//Name: maya_hair.ma (written by scripts/gen_interop_scenes.py)
requires maya "2020";
currentUnit -l centimeter -a degree -t film;
fileInfo "application" "maya";
createNode transform -s -n "persp";
	setAttr ".v" no;
	setAttr ".t" -type "double3" 28 21 28 ;
createNode camera -s -n "perspShape" -p "persp";
	setAttr -k off ".v" no;
	setAttr ".fl" 34.999999999999993;
createNode transform -s -n "top";
	setAttr ".v" no;
createNode camera -s -n "topShape" -p "top";
	setAttr ".rnd" no;
	setAttr ".o" yes;
createNode transform -n "renderCam";
	setAttr ".t" -type "double3" 0 1.9 5.2 ;
	setAttr ".r" -type "double3" -8.7462 0 0 ;
createNode camera -n "renderCamShape" -p "renderCam";
	setAttr ".fl" 45;
	setAttr ".coi" 5.2612;
createNode transform -n "ground";
createNode mesh -n "groundShape" -p "ground";
	setAttr ".uvst[0].uvsn" -type "string" "map1";
	setAttr -s 4 ".uvst[0].uvsp[0:3]" -type "float2" 0 0 1 0 0 1 1 1;
	setAttr -s 4 ".vt[0:3]"  -4 0 4 4 0 4 -4 0 -4 4 0 -4;
	setAttr -s 4 ".ed[0:3]"  0 1 0 0 2 0 1 3 0 2 3 0;
	setAttr -ch 4 ".fc[0]" -type "polyFaces" 
		f 4 0 2 -4 -2
		mu 0 4 0 1 3 2 ;
createNode transform -n "head";
	setAttr ".t" -type "double3" 0 1.1 0 ;
createNode mesh -n "headShape" -p "head";
createNode polySphere -n "polySphere1";
	setAttr ".sa" 40;
	setAttr ".sh" 40;
createNode lambert -n "skin";
	setAttr ".c" -type "float3" 0.9 0.68 0.55 ;
createNode shadingEngine -n "skinSG";
createNode transform -n "hairSystem1";
createNode hairSystem -n "hairSystemShape1" -p "hairSystem1";
	setAttr ".hpc" 60;
	setAttr ".cwd" 0.22;
	setAttr ".hwd" 0.006;
	setAttr ".ssg" 2;
	setAttr ".thn" 0.2;
	setAttr -s 2 ".cws[0:1]"  0 1 2 1 0.25 2;
	setAttr -s 2 ".hws[0:1]"  0.8 1 1 1 0.3 1;
	setAttr ".clc[0]"  0 0.5 1;
	setAttr ".noi" 0.6;
	setAttr ".nof" 0.6;
	setAttr ".hcl" -type "float3" 0.33 0.19 0.09 ;
	setAttr ".hcs[0].hcsp" 0;
	setAttr ".hcs[0].hcsc" -type "float3" 0.6 0.6 0.6 ;
	setAttr ".hcs[0].hcsi" 1;
	setAttr ".hcs[1].hcsp" 1;
	setAttr ".hcs[1].hcsc" -type "float3" 1.1 1.05 1 ;
	setAttr ".hcs[1].hcsi" 1;
	setAttr ".spc" -type "float3" 0.3 0.28 0.25 ;
	setAttr ".spp" 30;
createNode transform -n "hairSystem1Follicles";
createNode transform -n "follicle1" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.22733 2.0738 0.0049566 ;
createNode follicle -n "follicle1Shape" -p "follicle1";
	setAttr ".pu" 0.0034696;
	setAttr ".pv" 0.92698;
createNode transform -n "curve1" -p "follicle1";
createNode nurbsCurve -n "curve1Shape" -p "curve1";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.17709 -0.032 0.0038612
		0.49436 -0.23208 0.010779
		0.78674 -0.72239 0.017154
		0.78461 -1.4581 0.017107
		0.592 -2.2124 0.012908
		0.2606 -2.8618 0.005682
		;
createNode transform -n "follicle2" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.39278 2.0176 0.061783 ;
createNode follicle -n "follicle2Shape" -p "follicle2";
	setAttr ".pu" 0.024831;
	setAttr ".pv" 0.86984;
createNode transform -n "curve2" -p "follicle2";
createNode nurbsCurve -n "curve2Shape" -p "curve2";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.15553 -0.055845 0.024465
		0.41534 -0.28351 0.065333
		0.62881 -0.76735 0.098911
		0.58774 -1.4514 0.092451
		0.39633 -2.1673 0.062342
		0.089336 -2.7899 0.014052
		;
createNode transform -n "follicle3" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.55469 1.9318 0.020019 ;
createNode follicle -n "follicle3Shape" -p "follicle3";
	setAttr ".pu" 0.0057416;
	setAttr ".pv" 0.8127;
createNode transform -n "curve3" -p "follicle3";
createNode nurbsCurve -n "curve3Shape" -p "curve3";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.13509 -0.074048 0.0048754
		0.34306 -0.3178 0.012381
		0.48855 -0.78428 0.017632
		0.41409 -1.4635 0.014945
		0.22218 -2.154 0.0080189
		-0.066968 -2.7628 -0.002417
		;
createNode transform -n "follicle4" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.68998 1.8193 0.080472 ;
createNode follicle -n "follicle4Shape" -p "follicle4";
	setAttr ".pu" 0.018479;
	setAttr ".pv" 0.75556;
createNode transform -n "curve4" -p "follicle4";
createNode nurbsCurve -n "curve4Shape" -p "curve4";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.11089 -0.086487 0.012933
		0.26468 -0.33535 0.030869
		0.34651 -0.77494 0.040413
		0.24645 -1.4271 0.028744
		0.06019 -2.0881 0.0070199
		-0.20523 -2.6787 -0.023935
		;
createNode transform -n "follicle5" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.81194 1.6837 0.0020495 ;
createNode follicle -n "follicle5Shape" -p "follicle5";
	setAttr ".pu" 0.00040174;
	setAttr ".pv" 0.69841;
createNode transform -n "curve5" -p "follicle5";
createNode nurbsCurve -n "curve5Shape" -p "curve5";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.088123 -0.093321 0.00022244
		0.19328 -0.33725 0.00048788
		0.22102 -0.74194 0.00055789
		0.10084 -1.3372 0.00025454
		-0.079482 -1.9625 -0.00020063
		-0.3239 -2.5283 -0.00081758
		;
createNode transform -n "follicle6" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.89696 1.5294 0.10534 ;
createNode follicle -n "follicle6Shape" -p "follicle6";
	setAttr ".pu" 0.018606;
	setAttr ".pv" 0.64127;
createNode transform -n "curve6" -p "follicle6";
createNode nurbsCurve -n "curve6Shape" -p "curve6";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.065341 -0.094967 0.0076735
		0.12576 -0.32519 0.014769
		0.10846 -0.68864 0.012738
		-0.023453 -1.1908 -0.0027542
		-0.1928 -1.7725 -0.022642
		-0.41225 -2.3054 -0.048414
		;
createNode transform -n "follicle7" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.96488 1.3612 0.027582 ;
createNode follicle -n "follicle7Shape" -p "follicle7";
	setAttr ".pu" 0.0045484;
	setAttr ".pv" 0.58413;
createNode transform -n "curve7" -p "follicle7";
createNode nurbsCurve -n "curve7Shape" -p "curve7";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.045649 -0.092067 0.0013049
		0.068916 -0.30136 0.0019701
		0.016561 -0.619 0.00047341
		-0.12214 -1.1724 -0.0034915
		-0.28026 -1.7479 -0.0080115
		-0.47704 -2.2844 -0.013637
		;
createNode transform -n "follicle8" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.22125 2.0738 0.052443 ;
createNode follicle -n "follicle8Shape" -p "follicle8";
	setAttr ".pu" 0.037041;
	setAttr ".pv" 0.92698;
createNode transform -n "curve8" -p "follicle8";
createNode nurbsCurve -n "curve8Shape" -p "curve8";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.17235 -0.032 0.040853
		0.48114 -0.23208 0.11404
		0.76571 -0.72239 0.1815
		0.76364 -1.4678 0.181
		0.57618 -2.2245 0.13657
		0.25363 -2.8763 0.060118
		;
createNode transform -n "follicle9" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.36941 2.0176 0.14705 ;
createNode follicle -n "follicle9Shape" -p "follicle9";
	setAttr ".pu" 0.060294;
	setAttr ".pv" 0.86984;
createNode transform -n "curve9" -p "follicle9";
createNode nurbsCurve -n "curve9Shape" -p "curve9";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.14628 -0.055845 0.058229
		0.39064 -0.28351 0.1555
		0.59141 -0.76735 0.23542
		0.55278 -1.5681 0.22004
		0.37276 -2.3132 0.14838
		0.084022 -2.9649 0.033446
		;
createNode transform -n "follicle10" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.53593 1.9318 0.14444 ;
createNode follicle -n "follicle10Shape" -p "follicle10";
	setAttr ".pu" 0.041898;
	setAttr ".pv" 0.8127;
createNode transform -n "curve10" -p "follicle10";
createNode nurbsCurve -n "curve10Shape" -p "curve10";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.13052 -0.074048 0.035175
		0.33146 -0.3178 0.08933
		0.47202 -0.78428 0.12721
		0.40008 -1.4676 0.10782
		0.21467 -2.1592 0.057854
		-0.064703 -2.769 -0.017438
		;
createNode transform -n "follicle11" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.63919 1.8193 0.272 ;
createNode follicle -n "follicle11Shape" -p "follicle11";
	setAttr ".pu" 0.064031;
	setAttr ".pv" 0.75556;
createNode transform -n "curve11" -p "follicle11";
createNode nurbsCurve -n "curve11Shape" -p "curve11";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.10273 -0.086487 0.043714
		0.2452 -0.33535 0.10434
		0.32101 -0.77494 0.1366
		0.22831 -1.3657 0.097154
		0.055759 -2.0113 0.023727
		-0.19012 -2.5865 -0.080902
		;
createNode transform -n "follicle12" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.77982 1.6837 0.22609 ;
createNode follicle -n "follicle12Shape" -p "follicle12";
	setAttr ".pu" 0.044912;
	setAttr ".pv" 0.69841;
createNode transform -n "curve12" -p "follicle12";
createNode nurbsCurve -n "curve12Shape" -p "curve12";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.084638 -0.093321 0.024539
		0.18564 -0.33725 0.053821
		0.21228 -0.74194 0.061545
		0.096852 -1.318 0.02808
		-0.076339 -1.9385 -0.022133
		-0.31109 -2.4995 -0.090193
		;
createNode transform -n "follicle13" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.93934 1.3612 0.22225 ;
createNode follicle -n "follicle13Shape" -p "follicle13";
	setAttr ".pu" 0.036976;
	setAttr ".pv" 0.58413;
createNode transform -n "curve13" -p "follicle13";
createNode nurbsCurve -n "curve13Shape" -p "curve13";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.044441 -0.092067 0.010515
		0.067092 -0.30136 0.015874
		0.016122 -0.619 0.0038146
		-0.11891 -1.1032 -0.028134
		-0.27284 -1.6615 -0.064554
		-0.46442 -2.1808 -0.10988
		;
createNode transform -n "follicle14" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.19914 2.0738 0.10976 ;
createNode follicle -n "follicle14Shape" -p "follicle14";
	setAttr ".pu" 0.080173;
	setAttr ".pv" 0.92698;
createNode transform -n "curve14" -p "follicle14";
createNode nurbsCurve -n "curve14Shape" -p "curve14";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.15513 -0.032 0.085501
		0.43305 -0.23208 0.23868
		0.68918 -0.72239 0.37985
		0.68731 -1.4621 0.37882
		0.51859 -2.2174 0.28583
		0.22828 -2.8678 0.12582
		;
createNode transform -n "follicle15" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.32812 2.0176 0.22455 ;
createNode follicle -n "follicle15Shape" -p "follicle15";
	setAttr ".pu" 0.095517;
	setAttr ".pv" 0.86984;
createNode transform -n "curve15" -p "follicle15";
createNode nurbsCurve -n "curve15Shape" -p "curve15";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.12993 -0.055845 0.088918
		0.34698 -0.28351 0.23746
		0.52531 -0.76735 0.3595
		0.49099 -1.5269 0.33602
		0.33109 -2.2617 0.22659
		0.074631 -2.9032 0.051074
		;
createNode transform -n "follicle16" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.49389 1.9318 0.25329 ;
createNode follicle -n "follicle16Shape" -p "follicle16";
	setAttr ".pu" 0.075419;
	setAttr ".pv" 0.8127;
createNode transform -n "curve16" -p "follicle16";
createNode nurbsCurve -n "curve16Shape" -p "curve16";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.12028 -0.074048 0.061684
		0.30546 -0.3178 0.15665
		0.435 -0.78428 0.22309
		0.3687 -1.4878 0.18909
		0.19783 -2.1844 0.10146
		-0.059628 -2.7992 -0.03058
		;
createNode transform -n "follicle17" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.17362 2.0738 0.14683 ;
createNode follicle -n "follicle17Shape" -p "follicle17";
	setAttr ".pu" 0.11172;
	setAttr ".pv" 0.92698;
createNode transform -n "curve17" -p "follicle17";
createNode nurbsCurve -n "curve17Shape" -p "curve17";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.13525 -0.032 0.11438
		0.37756 -0.23208 0.3193
		0.60087 -0.72239 0.50814
		0.59924 -1.4799 0.50677
		0.45214 -2.2396 0.38237
		0.19903 -2.8945 0.16832
		;
createNode transform -n "follicle18" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.26985 2.0176 0.29201 ;
createNode follicle -n "follicle18Shape" -p "follicle18";
	setAttr ".pu" 0.13127;
	setAttr ".pv" 0.86984;
createNode transform -n "curve18" -p "follicle18";
createNode nurbsCurve -n "curve18Shape" -p "curve18";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.10685 -0.055845 0.11563
		0.28536 -0.28351 0.30879
		0.43202 -0.76735 0.46749
		0.4038 -1.5022 0.43696
		0.27229 -2.2308 0.29465
		0.061377 -2.866 0.066417
		;
createNode transform -n "follicle19" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.42689 1.9318 0.35476 ;
createNode follicle -n "follicle19Shape" -p "follicle19";
	setAttr ".pu" 0.11035;
	setAttr ".pv" 0.8127;
createNode transform -n "curve19" -p "follicle19";
createNode nurbsCurve -n "curve19Shape" -p "curve19";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.10396 -0.074048 0.086395
		0.26402 -0.3178 0.21941
		0.37598 -0.78428 0.31245
		0.31868 -1.5207 0.26483
		0.17099 -2.2255 0.1421
		-0.051538 -2.8485 -0.04283
		;
createNode transform -n "follicle20" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.13106 2.0738 0.18581 ;
createNode follicle -n "follicle20Shape" -p "follicle20";
	setAttr ".pu" 0.15223;
	setAttr ".pv" 0.92698;
createNode transform -n "curve20" -p "follicle20";
createNode nurbsCurve -n "curve20Shape" -p "curve20";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.10209 -0.032 0.14475
		0.285 -0.23208 0.40408
		0.45356 -0.72239 0.64306
		0.45234 -1.5353 0.64132
		0.3413 -2.3089 0.48389
		0.15024 -2.9775 0.21301
		;
createNode transform -n "follicle21" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.20497 2.0176 0.3407 ;
createNode follicle -n "follicle21Shape" -p "follicle21";
	setAttr ".pu" 0.1638;
	setAttr ".pv" 0.86984;
createNode transform -n "curve21" -p "follicle21";
createNode nurbsCurve -n "curve21Shape" -p "curve21";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.081165 -0.055845 0.13491
		0.21675 -0.28351 0.36027
		0.32815 -0.76735 0.54544
		0.30672 -1.5724 0.50981
		0.20683 -2.3186 0.34378
		0.046621 -2.9714 0.077491
		;
createNode transform -n "follicle22" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.34261 1.9318 0.43669 ;
createNode follicle -n "follicle22Shape" -p "follicle22";
	setAttr ".pu" 0.14412;
	setAttr ".pv" 0.8127;
createNode transform -n "curve22" -p "follicle22";
createNode nurbsCurve -n "curve22Shape" -p "curve22";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.083437 -0.074048 0.10635
		0.21189 -0.3178 0.27008
		0.30176 -0.78428 0.38462
		0.25577 -1.4705 0.326
		0.13723 -2.1628 0.17492
		-0.041364 -2.7733 -0.052723
		;
createNode transform -n "follicle23" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.089344 2.0738 0.20909 ;
createNode follicle -n "follicle23Shape" -p "follicle23";
	setAttr ".pu" 0.18573;
	setAttr ".pv" 0.92698;
createNode transform -n "curve23" -p "follicle23";
createNode nurbsCurve -n "curve23Shape" -p "curve23";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.069599 -0.032 0.16288
		0.19429 -0.23208 0.4547
		0.30921 -0.72239 0.72363
		0.30837 -1.5399 0.72167
		0.23267 -2.3147 0.54452
		0.10242 -2.9846 0.23969
		;
createNode transform -n "follicle24" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.11675 2.0176 0.38008 ;
createNode follicle -n "follicle24Shape" -p "follicle24";
	setAttr ".pu" 0.20257;
	setAttr ".pv" 0.86984;
createNode transform -n "curve24" -p "follicle24";
createNode nurbsCurve -n "curve24Shape" -p "curve24";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.04623 -0.055845 0.1505
		0.12346 -0.28351 0.40192
		0.18691 -0.76735 0.60848
		0.1747 -1.5585 0.56874
		0.11781 -2.3012 0.38352
		0.026554 -2.9505 0.086448
		;
createNode transform -n "follicle25" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.23021 1.9318 0.50506 ;
createNode follicle -n "follicle25Shape" -p "follicle25";
	setAttr ".pu" 0.18193;
	setAttr ".pv" 0.8127;
createNode transform -n "curve25" -p "follicle25";
createNode nurbsCurve -n "curve25Shape" -p "curve25";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.056065 -0.074048 0.123
		0.14238 -0.3178 0.31237
		0.20276 -0.78428 0.44483
		0.17186 -1.5074 0.37704
		0.092213 -2.209 0.2023
		-0.027794 -2.8287 -0.060976
		;
createNode transform -n "follicle26" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.036406 2.0738 0.22445 ;
createNode follicle -n "follicle26Shape" -p "follicle26";
	setAttr ".pu" 0.22441;
	setAttr ".pv" 0.92698;
createNode transform -n "curve26" -p "follicle26";
createNode nurbsCurve -n "curve26Shape" -p "curve26";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.02836 -0.032 0.17484
		0.079171 -0.23208 0.48809
		0.126 -0.72239 0.77677
		0.12565 -1.5012 0.77467
		0.094809 -2.2663 0.5845
		0.041735 -2.9265 0.2573
		;
createNode transform -n "follicle27" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.026814 2.0176 0.3967 ;
createNode follicle -n "follicle27Shape" -p "follicle27";
	setAttr ".pu" 0.23926;
	setAttr ".pv" 0.86984;
createNode transform -n "curve27" -p "follicle27";
createNode nurbsCurve -n "curve27Shape" -p "curve27";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.010618 -0.055845 0.15708
		0.028354 -0.28351 0.41949
		0.042927 -0.76735 0.63509
		0.040123 -1.4498 0.59361
		0.027056 -2.1654 0.40029
		0.0060987 -2.7875 0.090228
		;
createNode transform -n "follicle28" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.097828 1.9318 0.54636 ;
createNode follicle -n "follicle28Shape" -p "follicle28";
	setAttr ".pu" 0.2218;
	setAttr ".pv" 0.8127;
createNode transform -n "curve28" -p "follicle28";
createNode nurbsCurve -n "curve28Shape" -p "curve28";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.023824 -0.074048 0.13306
		0.060504 -0.3178 0.33791
		0.086163 -0.78428 0.48121
		0.073031 -1.501 0.40787
		0.039185 -2.2009 0.21885
		-0.011811 -2.8191 -0.065963
		;
createNode transform -n "follicle29" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.010232 2.0738 0.22715 ;
createNode follicle -n "follicle29Shape" -p "follicle29";
	setAttr ".pu" 0.25716;
	setAttr ".pv" 0.92698;
createNode transform -n "curve29" -p "follicle29";
createNode nurbsCurve -n "curve29Shape" -p "curve29";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.0079705 -0.032 0.17695
		-0.022251 -0.23208 0.49397
		-0.03541 -0.72239 0.78613
		-0.035315 -1.441 0.784
		-0.026646 -2.1911 0.59154
		-0.011729 -2.8362 0.2604
		;
createNode transform -n "follicle30" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.056775 2.0176 0.39353 ;
createNode follicle -n "follicle30Shape" -p "follicle30";
	setAttr ".pu" 0.2728;
	setAttr ".pv" 0.86984;
createNode transform -n "curve30" -p "follicle30";
createNode nurbsCurve -n "curve30Shape" -p "curve30";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.022481 -0.055845 0.15583
		-0.060037 -0.28351 0.41614
		-0.090893 -0.76735 0.63002
		-0.084956 -1.4642 0.58887
		-0.057288 -2.1833 0.39709
		-0.012913 -2.809 0.089508
		;
createNode transform -n "follicle31" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.0043754 1.9318 0.55503 ;
createNode follicle -n "follicle31Shape" -p "follicle31";
	setAttr ".pu" 0.25125;
	setAttr ".pv" 0.8127;
createNode transform -n "curve31" -p "follicle31";
createNode nurbsCurve -n "curve31Shape" -p "curve31";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.0010656 -0.074048 0.13517
		-0.002706 -0.3178 0.34327
		-0.0038536 -0.78428 0.48885
		-0.0032663 -1.4226 0.41435
		-0.0017526 -2.1029 0.22232
		0.00052824 -2.7014 -0.06701
		;
createNode transform -n "follicle32" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.063507 2.0738 0.21833 ;
createNode follicle -n "follicle32Shape" -p "follicle32";
	setAttr ".pu" 0.29505;
	setAttr ".pv" 0.92698;
createNode transform -n "curve32" -p "follicle32";
createNode nurbsCurve -n "curve32Shape" -p "curve32";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.049472 -0.032 0.17008
		-0.13811 -0.23208 0.4748
		-0.21979 -0.72239 0.75561
		-0.21919 -1.4488 0.75356
		-0.16538 -2.2007 0.56858
		-0.072802 -2.8478 0.25029
		;
createNode transform -n "follicle33" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.14261 2.0176 0.37115 ;
createNode follicle -n "follicle33Shape" -p "follicle33";
	setAttr ".pu" 0.30838;
	setAttr ".pv" 0.86984;
createNode transform -n "curve33" -p "follicle33";
createNode nurbsCurve -n "curve33Shape" -p "curve33";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.056469 -0.055845 0.14697
		-0.1508 -0.28351 0.39248
		-0.22831 -0.76735 0.59419
		-0.21339 -1.515 0.55538
		-0.1439 -2.2468 0.37451
		-0.032436 -2.8853 0.084417
		;
createNode transform -n "follicle34" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.15545 1.9318 0.53284 ;
createNode follicle -n "follicle34Shape" -p "follicle34";
	setAttr ".pu" 0.29518;
	setAttr ".pv" 0.8127;
createNode transform -n "curve34" -p "follicle34";
createNode nurbsCurve -n "curve34Shape" -p "curve34";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.037859 -0.074048 0.12976
		-0.096144 -0.3178 0.32955
		-0.13692 -0.78428 0.4693
		-0.11605 -1.524 0.39778
		-0.062268 -2.2296 0.21343
		0.018768 -2.8535 -0.06433
		;
createNode transform -n "follicle35" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.11067 2.0738 0.19863 ;
createNode follicle -n "follicle35Shape" -p "follicle35";
	setAttr ".pu" 0.3309;
	setAttr ".pv" 0.92698;
createNode transform -n "curve35" -p "follicle35";
createNode nurbsCurve -n "curve35Shape" -p "curve35";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.086211 -0.032 0.15473
		-0.24067 -0.23208 0.43195
		-0.38301 -0.72239 0.68743
		-0.38197 -1.5657 0.68557
		-0.2882 -2.3469 0.51727
		-0.12687 -3.0232 0.2277
		;
createNode transform -n "follicle36" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.21495 2.0176 0.3345 ;
createNode follicle -n "follicle36Shape" -p "follicle36";
	setAttr ".pu" 0.3409;
	setAttr ".pv" 0.86984;
createNode transform -n "curve36" -p "follicle36";
createNode nurbsCurve -n "curve36Shape" -p "curve36";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.085115 -0.055845 0.13245
		-0.2273 -0.28351 0.35371
		-0.34412 -0.76735 0.53551
		-0.32164 -1.4653 0.50053
		-0.21689 -2.1846 0.33752
		-0.048889 -2.8106 0.07608
		;
createNode transform -n "follicle37" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.24861 1.9318 0.49626 ;
createNode follicle -n "follicle37Shape" -p "follicle37";
	setAttr ".pu" 0.32391;
	setAttr ".pv" 0.8127;
createNode transform -n "curve37" -p "follicle37";
createNode nurbsCurve -n "curve37Shape" -p "curve37";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.060545 -0.074048 0.12086
		-0.15376 -0.3178 0.30693
		-0.21896 -0.78428 0.43709
		-0.18559 -1.4458 0.37047
		-0.099581 -2.132 0.19878
		0.030015 -2.7363 -0.059914
		;
createNode transform -n "follicle38" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.14673 2.0738 0.1737 ;
createNode follicle -n "follicle38Shape" -p "follicle38";
	setAttr ".pu" 0.36163;
	setAttr ".pv" 0.92698;
createNode transform -n "curve38" -p "follicle38";
createNode nurbsCurve -n "curve38Shape" -p "curve38";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.1143 -0.032 0.13532
		-0.31908 -0.23208 0.37775
		-0.50779 -0.72239 0.60116
		-0.50642 -1.4872 0.59954
		-0.3821 -2.2488 0.45236
		-0.1682 -2.9055 0.19913
		;
createNode transform -n "follicle39" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.29166 2.0176 0.27023 ;
createNode follicle -n "follicle39Shape" -p "follicle39";
	setAttr ".pu" 0.38107;
	setAttr ".pv" 0.86984;
createNode transform -n "curve39" -p "follicle39";
createNode nurbsCurve -n "curve39Shape" -p "curve39";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.11549 -0.055845 0.107
		-0.30842 -0.28351 0.28576
		-0.46693 -0.76735 0.43262
		-0.43643 -1.5688 0.40436
		-0.2943 -2.3141 0.27267
		-0.066338 -2.966 0.061463
		;
createNode transform -n "follicle40" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.36586 1.9318 0.41741 ;
createNode follicle -n "follicle40Shape" -p "follicle40";
	setAttr ".pu" 0.36454;
	setAttr ".pv" 0.8127;
createNode transform -n "curve40" -p "follicle40";
createNode nurbsCurve -n "curve40Shape" -p "curve40";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.0891 -0.074048 0.10165
		-0.22627 -0.3178 0.25816
		-0.32223 -0.78428 0.36763
		-0.27312 -1.4835 0.3116
		-0.14655 -2.179 0.16719
		0.044171 -2.7927 -0.050394
		;
createNode transform -n "follicle41" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.18497 2.0738 0.13224 ;
createNode follicle -n "follicle41Shape" -p "follicle41";
	setAttr ".pu" 0.40121;
	setAttr ".pv" 0.92698;
createNode transform -n "curve41" -p "follicle41";
createNode nurbsCurve -n "curve41Shape" -p "curve41";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.14409 -0.032 0.10302
		-0.40224 -0.23208 0.28758
		-0.64015 -0.72239 0.45767
		-0.63841 -1.5546 0.45643
		-0.4817 -2.333 0.34439
		-0.21204 -3.0065 0.1516
		;
createNode transform -n "follicle42" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.34753 2.0176 0.19316 ;
createNode follicle -n "follicle42Shape" -p "follicle42";
	setAttr ".pu" 0.41926;
	setAttr ".pv" 0.86984;
createNode transform -n "curve42" -p "follicle42";
createNode nurbsCurve -n "curve42Shape" -p "curve42";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.13762 -0.055845 0.076487
		-0.3675 -0.28351 0.20426
		-0.55638 -0.76735 0.30924
		-0.52004 -1.4941 0.28904
		-0.35068 -2.2206 0.19491
		-0.079046 -2.8539 0.043934
		;
createNode transform -n "follicle43" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.44309 1.9318 0.33429 ;
createNode follicle -n "follicle43Shape" -p "follicle43";
	setAttr ".pu" 0.39713;
	setAttr ".pv" 0.8127;
createNode transform -n "curve43" -p "follicle43";
createNode nurbsCurve -n "curve43Shape" -p "curve43";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.10791 -0.074048 0.081411
		-0.27404 -0.3178 0.20675
		-0.39026 -0.78428 0.29443
		-0.33078 -1.4285 0.24956
		-0.17748 -2.1104 0.1339
		0.053495 -2.7104 -0.040359
		;
createNode transform -n "follicle44" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.20593 2.0738 0.096412 ;
createNode follicle -n "follicle44Shape" -p "follicle44";
	setAttr ".pu" 0.43031;
	setAttr ".pv" 0.92698;
createNode transform -n "curve44" -p "follicle44";
createNode nurbsCurve -n "curve44Shape" -p "curve44";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.16042 -0.032 0.075105
		-0.44782 -0.23208 0.20966
		-0.71268 -0.72239 0.33367
		-0.71075 -1.4833 0.33276
		-0.53628 -2.244 0.25108
		-0.23607 -2.8996 0.11052
		;
createNode transform -n "follicle45" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.37576 2.0176 0.12999 ;
createNode follicle -n "follicle45Shape" -p "follicle45";
	setAttr ".pu" 0.44699;
	setAttr ".pv" 0.86984;
createNode transform -n "curve45" -p "follicle45";
createNode nurbsCurve -n "curve45Shape" -p "curve45";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.14879 -0.055845 0.051474
		-0.39735 -0.28351 0.13746
		-0.60156 -0.76735 0.20811
		-0.56227 -1.4418 0.19452
		-0.37916 -2.1553 0.13117
		-0.085465 -2.7754 0.029566
		;
createNode transform -n "follicle46" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.50251 1.9318 0.23572 ;
createNode follicle -n "follicle46Shape" -p "follicle46";
	setAttr ".pu" 0.43019;
	setAttr ".pv" 0.8127;
createNode transform -n "curve46" -p "follicle46";
createNode nurbsCurve -n "curve46Shape" -p "curve46";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.12238 -0.074048 0.057407
		-0.31079 -0.3178 0.14579
		-0.44259 -0.78428 0.20762
		-0.37514 -1.4283 0.17597
		-0.20128 -2.11 0.09442
		0.060669 -2.7099 -0.028459
		;
createNode transform -n "follicle47" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.6611 1.8193 0.21331 ;
createNode follicle -n "follicle47Shape" -p "follicle47";
	setAttr ".pu" 0.45032;
	setAttr ".pv" 0.75556;
createNode transform -n "curve47" -p "follicle47";
createNode nurbsCurve -n "curve47Shape" -p "curve47";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.10625 -0.086487 0.034283
		-0.2536 -0.33535 0.081828
		-0.33201 -0.77494 0.10713
		-0.23614 -1.3629 0.076193
		-0.05767 -2.0078 0.018608
		0.19664 -2.5823 -0.063448
		;
createNode transform -n "follicle48" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.86404 1.5294 0.2628 ;
createNode follicle -n "follicle48Shape" -p "follicle48";
	setAttr ".pu" 0.45301;
	setAttr ".pv" 0.64127;
createNode transform -n "curve48" -p "follicle48";
createNode nurbsCurve -n "curve48Shape" -p "curve48";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.062943 -0.094967 0.019144
		-0.12114 -0.32519 0.036845
		-0.10448 -0.68864 0.031779
		0.022592 -1.1985 -0.0068713
		0.18572 -1.7822 -0.056487
		0.39712 -2.3169 -0.12078
		;
createNode transform -n "follicle49" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.2228 2.0738 0.045399 ;
createNode follicle -n "follicle49Shape" -p "follicle49";
	setAttr ".pu" 0.46801;
	setAttr ".pv" 0.92698;
createNode transform -n "curve49" -p "follicle49";
createNode nurbsCurve -n "curve49Shape" -p "curve49";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.17356 -0.032 0.035366
		-0.48452 -0.23208 0.098728
		-0.77108 -0.72239 0.15712
		-0.76899 -1.4866 0.15669
		-0.58022 -2.248 0.11823
		-0.25541 -2.9045 0.052044
		;
createNode transform -n "follicle50" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.39546 2.0176 0.041249 ;
createNode follicle -n "follicle50Shape" -p "follicle50";
	setAttr ".pu" 0.48346;
	setAttr ".pv" 0.86984;
createNode transform -n "curve50" -p "follicle50";
createNode nurbsCurve -n "curve50Shape" -p "curve50";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.15659 -0.055845 0.016334
		-0.41818 -0.28351 0.043619
		-0.63311 -0.76735 0.066037
		-0.59175 -1.5549 0.061723
		-0.39904 -2.2967 0.041622
		-0.089946 -2.9452 0.0093819
		;
createNode transform -n "follicle51" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.54818 1.9318 0.087084 ;
createNode follicle -n "follicle51Shape" -p "follicle51";
	setAttr ".pu" 0.47493;
	setAttr ".pv" 0.8127;
createNode transform -n "curve51" -p "follicle51";
createNode nurbsCurve -n "curve51Shape" -p "curve51";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.1335 -0.074048 0.021208
		-0.33903 -0.3178 0.053859
		-0.48281 -0.78428 0.0767
		-0.40923 -1.4769 0.06501
		-0.21958 -2.1708 0.034882
		0.066182 -2.7828 -0.010514
		;
createNode transform -n "follicle52" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.69246 1.8193 0.055256 ;
createNode follicle -n "follicle52Shape" -p "follicle52";
	setAttr ".pu" 0.48733;
	setAttr ".pv" 0.75556;
createNode transform -n "curve52" -p "follicle52";
createNode nurbsCurve -n "curve52Shape" -p "curve52";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.11129 -0.086487 0.0088805
		-0.26563 -0.33535 0.021196
		-0.34776 -0.77494 0.02775
		-0.24734 -1.3709 0.019737
		-0.060406 -2.0179 0.0048202
		0.20596 -2.5943 -0.016435
		;
createNode transform -n "follicle53" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.79281 1.6837 0.17522 ;
createNode follicle -n "follicle53Shape" -p "follicle53";
	setAttr ".pu" 0.46538;
	setAttr ".pv" 0.69841;
createNode transform -n "curve53" -p "follicle53";
createNode nurbsCurve -n "curve53Shape" -p "curve53";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.086047 -0.093321 0.019018
		-0.18873 -0.33725 0.041712
		-0.21581 -0.74194 0.047698
		-0.098464 -1.3251 0.021762
		0.07761 -1.9473 -0.017153
		0.31627 -2.5101 -0.0699
		;
createNode transform -n "follicle54" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.8991 1.5294 0.085107 ;
createNode follicle -n "follicle54Shape" -p "follicle54";
	setAttr ".pu" 0.48498;
	setAttr ".pv" 0.64127;
createNode transform -n "curve54" -p "follicle54";
createNode nurbsCurve -n "curve54Shape" -p "curve54";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.065497 -0.094967 0.0061998
		-0.12606 -0.32519 0.011932
		-0.10872 -0.68864 0.010292
		0.023509 -1.2892 -0.0022253
		0.19326 -1.8956 -0.018293
		0.41323 -2.453 -0.039116
		;
createNode transform -n "follicle55" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.94335 1.3612 0.20455 ;
createNode follicle -n "follicle55Shape" -p "follicle55";
	setAttr ".pu" 0.46602;
	setAttr ".pv" 0.58413;
createNode transform -n "curve55" -p "follicle55";
createNode nurbsCurve -n "curve55Shape" -p "curve55";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.04463 -0.092067 0.0096775
		-0.067378 -0.30136 0.01461
		-0.016191 -0.619 0.0035109
		0.11941 -1.0652 -0.025894
		0.274 -1.614 -0.059414
		0.4664 -2.1237 -0.10113
		;
createNode transform -n "follicle56" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.22691 2.0738 -0.014547 ;
createNode follicle -n "follicle56Shape" -p "follicle56";
	setAttr ".pu" 0.51019;
	setAttr ".pv" 0.92698;
createNode transform -n "curve56" -p "follicle56";
createNode nurbsCurve -n "curve56Shape" -p "curve56";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.17677 -0.032 -0.011332
		-0.49346 -0.23208 -0.031635
		-0.78531 -0.72239 -0.050345
		-0.78319 -1.5084 -0.050208
		-0.59093 -2.2753 -0.037883
		-0.26013 -2.9373 -0.016676
		;
createNode transform -n "follicle57" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.39465 2.0176 -0.048415 ;
createNode follicle -n "follicle57Shape" -p "follicle57";
	setAttr ".pu" 0.51943;
	setAttr ".pv" 0.86984;
createNode transform -n "curve57" -p "follicle57";
createNode nurbsCurve -n "curve57Shape" -p "curve57";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.15627 -0.055845 -0.019171
		-0.41732 -0.28351 -0.051197
		-0.63181 -0.76735 -0.077509
		-0.59054 -1.5142 -0.072446
		-0.39822 -2.2458 -0.048853
		-0.089761 -2.884 -0.011012
		;
createNode transform -n "follicle58" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.55505 1.9318 -0.0010105 ;
createNode follicle -n "follicle58Shape" -p "follicle58";
	setAttr ".pu" 0.50029;
	setAttr ".pv" 0.8127;
createNode transform -n "curve58" -p "follicle58";
createNode nurbsCurve -n "curve58Shape" -p "curve58";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.13517 -0.074048 -0.00024608
		-0.34328 -0.3178 -0.00062495
		-0.48887 -0.78428 -0.00088998
		-0.41436 -1.4852 -0.00075434
		-0.22233 -2.1811 -0.00040475
		0.067012 -2.7953 0.000122
		;
createNode transform -n "follicle59" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.68367 1.8193 -0.12305 ;
createNode follicle -n "follicle59Shape" -p "follicle59";
	setAttr ".pu" 0.52834;
	setAttr ".pv" 0.75556;
createNode transform -n "curve59" -p "follicle59";
createNode nurbsCurve -n "curve59Shape" -p "curve59";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.10988 -0.086487 -0.019776
		-0.26226 -0.33535 -0.047201
		-0.34334 -0.77494 -0.061795
		-0.2442 -1.4746 -0.043951
		-0.05964 -2.1474 -0.010734
		0.20335 -2.7498 0.036599
		;
createNode transform -n "follicle60" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.81105 1.6837 -0.03804 ;
createNode follicle -n "follicle60Shape" -p "follicle60";
	setAttr ".pu" 0.50746;
	setAttr ".pv" 0.69841;
createNode transform -n "curve60" -p "follicle60";
createNode nurbsCurve -n "curve60Shape" -p "curve60";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.088027 -0.093321 -0.0041287
		-0.19307 -0.33725 -0.0090554
		-0.22078 -0.74194 -0.010355
		-0.10073 -1.3142 -0.0047245
		0.079395 -1.9337 0.0037238
		0.32354 -2.4938 0.015175
		;
createNode transform -n "follicle61" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.89467 1.5294 -0.12324 ;
createNode follicle -n "follicle61Shape" -p "follicle61";
	setAttr ".pu" 0.52179;
	setAttr ".pv" 0.64127;
createNode transform -n "curve61" -p "follicle61";
createNode nurbsCurve -n "curve61Shape" -p "curve61";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.065175 -0.094967 -0.0089776
		-0.12544 -0.32519 -0.017279
		-0.10819 -0.68864 -0.014903
		0.023393 -1.201 0.0032223
		0.19231 -1.7853 0.02649
		0.4112 -2.3206 0.056642
		;
createNode transform -n "follicle62" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.96397 1.3612 -0.05014 ;
createNode follicle -n "follicle62Shape" -p "follicle62";
	setAttr ".pu" 0.50827;
	setAttr ".pv" 0.58413;
createNode transform -n "curve62" -p "follicle62";
createNode nurbsCurve -n "curve62Shape" -p "curve62";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.045606 -0.092067 -0.0023721
		-0.068851 -0.30136 -0.0035812
		-0.016545 -0.619 -0.00086057
		0.12202 -1.1331 0.0063469
		0.27999 -1.6989 0.014563
		0.47659 -2.2256 0.024789
		;
createNode transform -n "follicle63" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.21872 2.0738 -0.062148 ;
createNode follicle -n "follicle63Shape" -p "follicle63";
	setAttr ".pu" 0.54406;
	setAttr ".pv" 0.92698;
createNode transform -n "curve63" -p "follicle63";
createNode nurbsCurve -n "curve63Shape" -p "curve63";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.17038 -0.032 -0.048413
		-0.47565 -0.23208 -0.13515
		-0.75696 -0.72239 -0.21508
		-0.75491 -1.482 -0.2145
		-0.5696 -2.2422 -0.16185
		-0.25073 -2.8976 -0.071244
		;
createNode transform -n "follicle64" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.37328 2.0176 -0.13694 ;
createNode follicle -n "follicle64Shape" -p "follicle64";
	setAttr ".pu" 0.55596;
	setAttr ".pv" 0.86984;
createNode transform -n "curve64" -p "follicle64";
createNode nurbsCurve -n "curve64Shape" -p "curve64";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.14781 -0.055845 -0.054225
		-0.39473 -0.28351 -0.14481
		-0.5976 -0.76735 -0.21923
		-0.55856 -1.55 -0.20491
		-0.37666 -2.2905 -0.13818
		-0.084901 -2.9377 -0.031147
		;
createNode transform -n "follicle65" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.53176 1.9318 -0.15909 ;
createNode follicle -n "follicle65Shape" -p "follicle65";
	setAttr ".pu" 0.54627;
	setAttr ".pv" 0.8127;
createNode transform -n "curve65" -p "follicle65";
createNode nurbsCurve -n "curve65Shape" -p "curve65";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.1295 -0.074048 -0.038745
		-0.32888 -0.3178 -0.098395
		-0.46835 -0.78428 -0.14012
		-0.39697 -1.5284 -0.11877
		-0.213 -2.2352 -0.063726
		0.0642 -2.8602 0.019207
		;
createNode transform -n "follicle66" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.64227 1.8193 -0.26466 ;
createNode follicle -n "follicle66Shape" -p "follicle66";
	setAttr ".pu" 0.56221;
	setAttr ".pv" 0.75556;
createNode transform -n "curve66" -p "follicle66";
createNode nurbsCurve -n "curve66Shape" -p "curve66";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.10322 -0.086487 -0.042535
		-0.24638 -0.33535 -0.10152
		-0.32255 -0.77494 -0.13291
		-0.22941 -1.4686 -0.094532
		-0.056027 -2.1399 -0.023087
		0.19104 -2.7408 0.078719
		;
createNode transform -n "follicle67" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.7816 1.6837 -0.21986 ;
createNode follicle -n "follicle67Shape" -p "follicle67";
	setAttr ".pu" 0.54364;
	setAttr ".pv" 0.69841;
createNode transform -n "curve67" -p "follicle67";
createNode nurbsCurve -n "curve67Shape" -p "curve67";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.084831 -0.093321 -0.023862
		-0.18606 -0.33725 -0.052338
		-0.21276 -0.74194 -0.059848
		-0.097073 -1.3097 -0.027306
		0.076513 -1.928 0.021523
		0.3118 -2.4869 0.087707
		;
createNode transform -n "follicle68" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.84153 1.5294 -0.3278 ;
createNode follicle -n "follicle68Shape" -p "follicle68";
	setAttr ".pu" 0.55912;
	setAttr ".pv" 0.64127;
createNode transform -n "curve68" -p "follicle68";
createNode nurbsCurve -n "curve68Shape" -p "curve68";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.061303 -0.094967 -0.023879
		-0.11799 -0.32519 -0.045959
		-0.10176 -0.68864 -0.039639
		0.022003 -1.2261 0.008571
		0.18088 -1.8167 0.070459
		0.38677 -2.3583 0.15066
		;
createNode transform -n "follicle69" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.94066 1.3612 -0.21663 ;
createNode follicle -n "follicle69Shape" -p "follicle69";
	setAttr ".pu" 0.53602;
	setAttr ".pv" 0.58413;
createNode transform -n "curve69" -p "follicle69";
createNode nurbsCurve -n "curve69Shape" -p "curve69";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.044503 -0.092067 -0.010249
		-0.067185 -0.30136 -0.015473
		-0.016145 -0.619 -0.0037181
		0.11907 -1.0658 0.027422
		0.27322 -1.6148 0.062921
		0.46506 -2.1246 0.1071
		;
createNode transform -n "follicle70" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.20297 2.0738 -0.10249 ;
createNode follicle -n "follicle70Shape" -p "follicle70";
	setAttr ".pu" 0.57442;
	setAttr ".pv" 0.92698;
createNode transform -n "curve70" -p "follicle70";
createNode nurbsCurve -n "curve70Shape" -p "curve70";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.15811 -0.032 -0.079841
		-0.44139 -0.23208 -0.22289
		-0.70245 -0.72239 -0.35471
		-0.70055 -1.4726 -0.35375
		-0.52858 -2.2305 -0.26691
		-0.23268 -2.8835 -0.11749
		;
createNode transform -n "follicle71" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.32644 2.0176 -0.227 ;
createNode follicle -n "follicle71Shape" -p "follicle71";
	setAttr ".pu" 0.59671;
	setAttr ".pv" 0.86984;
createNode transform -n "curve71" -p "follicle71";
createNode nurbsCurve -n "curve71Shape" -p "curve71";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.12926 -0.055845 -0.089886
		-0.34519 -0.28351 -0.24004
		-0.52261 -0.76735 -0.36341
		-0.48847 -1.5693 -0.33967
		-0.32939 -2.3147 -0.22905
		-0.074247 -2.9667 -0.05163
		;
createNode transform -n "follicle72" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.49261 1.9318 -0.25577 ;
createNode follicle -n "follicle72Shape" -p "follicle72";
	setAttr ".pu" 0.57622;
	setAttr ".pv" 0.8127;
createNode transform -n "curve72" -p "follicle72";
createNode nurbsCurve -n "curve72Shape" -p "curve72";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.11997 -0.074048 -0.06229
		-0.30467 -0.3178 -0.15819
		-0.43387 -0.78428 -0.22527
		-0.36774 -1.5397 -0.19094
		-0.19732 -2.2493 -0.10245
		0.059473 -2.8771 0.03088
		;
createNode transform -n "follicle73" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.56232 1.8193 -0.40786 ;
createNode follicle -n "follicle73Shape" -p "follicle73";
	setAttr ".pu" 0.59987;
	setAttr ".pv" 0.75556;
createNode transform -n "curve73" -p "follicle73";
createNode nurbsCurve -n "curve73Shape" -p "curve73";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.090374 -0.086487 -0.06555
		-0.21571 -0.33535 -0.15646
		-0.2824 -0.77494 -0.20483
		-0.20085 -1.4868 -0.14568
		-0.049053 -2.1627 -0.035579
		0.16726 -2.7682 0.12131
		;
createNode transform -n "follicle74" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.72266 1.6837 -0.37014 ;
createNode follicle -n "follicle74Shape" -p "follicle74";
	setAttr ".pu" 0.57534;
	setAttr ".pv" 0.69841;
createNode transform -n "curve74" -p "follicle74";
createNode nurbsCurve -n "curve74Shape" -p "curve74";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.078434 -0.093321 -0.040173
		-0.17203 -0.33725 -0.088111
		-0.19672 -0.74194 -0.10076
		-0.089753 -1.3088 -0.04597
		0.070743 -1.927 0.036234
		0.28828 -2.4857 0.14765
		;
createNode transform -n "follicle75" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.75727 1.5294 -0.49211 ;
createNode follicle -n "follicle75Shape" -p "follicle75";
	setAttr ".pu" 0.59172;
	setAttr ".pv" 0.64127;
createNode transform -n "curve75" -p "follicle75";
createNode nurbsCurve -n "curve75Shape" -p "curve75";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.055165 -0.094967 -0.035849
		-0.10617 -0.32519 -0.068996
		-0.091573 -0.68864 -0.059508
		0.0198 -1.2049 0.012867
		0.16277 -1.7902 0.10578
		0.34805 -2.3266 0.22618
		;
createNode transform -n "follicle76" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.86384 1.3612 -0.43074 ;
createNode follicle -n "follicle76Shape" -p "follicle76";
	setAttr ".pu" 0.57362;
	setAttr ".pv" 0.58413;
createNode transform -n "curve76" -p "follicle76";
createNode nurbsCurve -n "curve76Shape" -p "curve76";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.040869 -0.092067 -0.020379
		-0.061699 -0.30136 -0.030766
		-0.014827 -0.619 -0.0073931
		0.10935 -1.1453 0.054526
		0.25091 -1.7141 0.12511
		0.42709 -2.2439 0.21296
		;
createNode transform -n "follicle77" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.16886 2.0738 -0.15228 ;
createNode follicle -n "follicle77Shape" -p "follicle77";
	setAttr ".pu" 0.61679;
	setAttr ".pv" 0.92698;
createNode transform -n "curve77" -p "follicle77";
createNode nurbsCurve -n "curve77Shape" -p "curve77";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.13154 -0.032 -0.11862
		-0.36721 -0.23208 -0.33115
		-0.58439 -0.72239 -0.52701
		-0.58281 -1.5501 -0.52558
		-0.43974 -2.3274 -0.39656
		-0.19357 -2.9997 -0.17456
		;
createNode transform -n "follicle78" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.27193 2.0176 -0.29008 ;
createNode follicle -n "follicle78Shape" -p "follicle78";
	setAttr ".pu" 0.63014;
	setAttr ".pv" 0.86984;
createNode transform -n "curve78" -p "follicle78";
createNode nurbsCurve -n "curve78Shape" -p "curve78";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.10768 -0.055845 -0.11486
		-0.28755 -0.28351 -0.30674
		-0.43534 -0.76735 -0.4644
		-0.40691 -1.5288 -0.43406
		-0.27439 -2.2641 -0.2927
		-0.06185 -2.906 -0.065977
		;
createNode transform -n "follicle79" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.41471 1.9318 -0.36892 ;
createNode follicle -n "follicle79Shape" -p "follicle79";
	setAttr ".pu" 0.61571;
	setAttr ".pv" 0.8127;
createNode transform -n "curve79" -p "follicle79";
createNode nurbsCurve -n "curve79Shape" -p "curve79";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.101 -0.074048 -0.089844
		-0.25649 -0.3178 -0.22817
		-0.36526 -0.78428 -0.32493
		-0.30959 -1.426 -0.27541
		-0.16611 -2.1072 -0.14777
		0.050068 -2.7066 0.04454
		;
createNode transform -n "follicle80" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.46888 1.8193 -0.51255 ;
createNode follicle -n "follicle80Shape" -p "follicle80";
	setAttr ".pu" 0.63208;
	setAttr ".pv" 0.75556;
createNode transform -n "curve80" -p "follicle80";
createNode nurbsCurve -n "curve80Shape" -p "curve80";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.075356 -0.086487 -0.082375
		-0.17986 -0.33535 -0.19662
		-0.23547 -0.77494 -0.2574
		-0.16748 -1.4808 -0.18308
		-0.040902 -2.1552 -0.044712
		0.13946 -2.7591 0.15245
		;
createNode transform -n "follicle81" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.60727 1.6837 -0.53895 ;
createNode follicle -n "follicle81Shape" -p "follicle81";
	setAttr ".pu" 0.61552;
	setAttr ".pv" 0.69841;
createNode transform -n "curve81" -p "follicle81";
createNode nurbsCurve -n "curve81Shape" -p "curve81";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.06591 -0.093321 -0.058495
		-0.14456 -0.33725 -0.1283
		-0.16531 -0.74194 -0.14671
		-0.075421 -1.3794 -0.066936
		0.059447 -2.0152 0.052759
		0.24225 -2.5916 0.215
		;
createNode transform -n "follicle82" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.61773 1.5294 -0.65882 ;
createNode follicle -n "follicle82Shape" -p "follicle82";
	setAttr ".pu" 0.63012;
	setAttr ".pv" 0.64127;
createNode transform -n "curve82" -p "follicle82";
createNode nurbsCurve -n "curve82Shape" -p "curve82";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.045 -0.094967 -0.047993
		-0.086607 -0.32519 -0.092369
		-0.074698 -0.68864 -0.079668
		0.016152 -1.2025 0.017226
		0.13278 -1.7872 0.14161
		0.28391 -2.3229 0.3028
		;
createNode transform -n "follicle83" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.72166 1.3612 -0.64106 ;
createNode follicle -n "follicle83Shape" -p "follicle83";
	setAttr ".pu" 0.6156;
	setAttr ".pv" 0.58413;
createNode transform -n "curve83" -p "follicle83";
createNode nurbsCurve -n "curve83Shape" -p "curve83";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.034142 -0.092067 -0.030329
		-0.051544 -0.30136 -0.045788
		-0.012386 -0.619 -0.011003
		0.091352 -1.1064 0.081149
		0.20961 -1.6655 0.1862
		0.35679 -2.1856 0.31695
		;
createNode transform -n "follicle84" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.13198 2.0738 -0.18515 ;
createNode follicle -n "follicle84Shape" -p "follicle84";
	setAttr ".pu" 0.65144;
	setAttr ".pv" 0.92698;
createNode transform -n "curve84" -p "follicle84";
createNode nurbsCurve -n "curve84Shape" -p "curve84";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.10281 -0.032 -0.14423
		-0.28702 -0.23208 -0.40265
		-0.45677 -0.72239 -0.64079
		-0.45554 -1.5676 -0.63905
		-0.34371 -2.3492 -0.48218
		-0.1513 -3.026 -0.21225
		;
createNode transform -n "follicle85" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.20249 2.0176 -0.34218 ;
createNode follicle -n "follicle85Shape" -p "follicle85";
	setAttr ".pu" 0.66496;
	setAttr ".pv" 0.86984;
createNode transform -n "curve85" -p "follicle85";
createNode nurbsCurve -n "curve85Shape" -p "curve85";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.080183 -0.055845 -0.13549
		-0.21413 -0.28351 -0.36184
		-0.32418 -0.76735 -0.54781
		-0.303 -1.4953 -0.51203
		-0.20433 -2.2222 -0.34528
		-0.046057 -2.8557 -0.077828
		;
createNode transform -n "follicle86" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.31773 1.9318 -0.45512 ;
createNode follicle -n "follicle86Shape" -p "follicle86";
	setAttr ".pu" 0.653;
	setAttr ".pv" 0.8127;
createNode transform -n "curve86" -p "follicle86";
createNode nurbsCurve -n "curve86Shape" -p "curve86";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.077377 -0.074048 -0.11084
		-0.1965 -0.3178 -0.28148
		-0.27984 -0.78428 -0.40085
		-0.23719 -1.5114 -0.33976
		-0.12727 -2.2139 -0.1823
		0.038359 -2.8346 0.054947
		;
createNode transform -n "follicle87" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.36282 1.8193 -0.59238 ;
createNode follicle -n "follicle87Shape" -p "follicle87";
	setAttr ".pu" 0.66254;
	setAttr ".pv" 0.75556;
createNode transform -n "curve87" -p "follicle87";
createNode nurbsCurve -n "curve87Shape" -p "curve87";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.058312 -0.086487 -0.095205
		-0.13918 -0.33535 -0.22724
		-0.18221 -0.77494 -0.29749
		-0.1296 -1.3764 -0.21159
		-0.031651 -2.0247 -0.051675
		0.10792 -2.6026 0.1762
		;
createNode transform -n "follicle88" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.49975 1.6837 -0.63992 ;
createNode follicle -n "follicle88Shape" -p "follicle88";
	setAttr ".pu" 0.64448;
	setAttr ".pv" 0.69841;
createNode transform -n "curve88" -p "follicle88";
createNode nurbsCurve -n "curve88Shape" -p "curve88";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.05424 -0.093321 -0.069453
		-0.11897 -0.33725 -0.15233
		-0.13604 -0.74194 -0.17419
		-0.062068 -1.4001 -0.079476
		0.048922 -2.041 0.062643
		0.19936 -2.6225 0.25528
		;
createNode transform -n "follicle89" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.43828 1.5294 -0.78964 ;
createNode follicle -n "follicle89Shape" -p "follicle89";
	setAttr ".pu" 0.66936;
	setAttr ".pv" 0.64127;
createNode transform -n "curve89" -p "follicle89";
createNode nurbsCurve -n "curve89Shape" -p "curve89";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.031928 -0.094967 -0.057523
		-0.061449 -0.32519 -0.11071
		-0.052999 -0.68864 -0.095487
		0.01146 -1.1982 0.020647
		0.094207 -1.7818 0.16973
		0.20144 -2.3165 0.36293
		;
createNode transform -n "follicle90" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.55894 1.3612 -0.78699 ;
createNode follicle -n "follicle90Shape" -p "follicle90";
	setAttr ".pu" 0.65171;
	setAttr ".pv" 0.58413;
createNode transform -n "curve90" -p "follicle90";
createNode nurbsCurve -n "curve90Shape" -p "curve90";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.026444 -0.092067 -0.037233
		-0.039922 -0.30136 -0.05621
		-0.0095934 -0.619 -0.013507
		0.070753 -1.1928 0.099621
		0.16235 -1.7735 0.22858
		0.27634 -2.3151 0.38909
		;
createNode transform -n "follicle91" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.089498 2.0738 -0.20903 ;
createNode follicle -n "follicle91Shape" -p "follicle91";
	setAttr ".pu" 0.68561;
	setAttr ".pv" 0.92698;
createNode transform -n "curve91" -p "follicle91";
createNode nurbsCurve -n "curve91Shape" -p "curve91";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.069719 -0.032 -0.16283
		-0.19463 -0.23208 -0.45456
		-0.30974 -0.72239 -0.7234
		-0.3089 -1.4847 -0.72145
		-0.23307 -2.2457 -0.54435
		-0.1026 -2.9017 -0.23962
		;
createNode transform -n "follicle92" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.11737 2.0176 -0.37989 ;
createNode follicle -n "follicle92Shape" -p "follicle92";
	setAttr ".pu" 0.70231;
	setAttr ".pv" 0.86984;
createNode transform -n "curve92" -p "follicle92";
createNode nurbsCurve -n "curve92Shape" -p "curve92";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.046477 -0.055845 -0.15043
		-0.12412 -0.28351 -0.40171
		-0.18791 -0.76735 -0.60818
		-0.17563 -1.4592 -0.56845
		-0.11843 -2.1771 -0.38332
		-0.026696 -2.8016 -0.086404
		;
createNode transform -n "follicle93" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.24035 1.9318 -0.50032 ;
createNode follicle -n "follicle93Shape" -p "follicle93";
	setAttr ".pu" 0.67872;
	setAttr ".pv" 0.8127;
createNode transform -n "curve93" -p "follicle93";
createNode nurbsCurve -n "curve93Shape" -p "curve93";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.058533 -0.074048 -0.12184
		-0.14865 -0.3178 -0.30943
		-0.21169 -0.78428 -0.44066
		-0.17943 -1.5442 -0.3735
		-0.096273 -2.2549 -0.2004
		0.029018 -2.8838 0.060404
		;
createNode transform -n "follicle94" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.20054 1.8193 -0.66508 ;
createNode follicle -n "follicle94Shape" -p "follicle94";
	setAttr ".pu" 0.70339;
	setAttr ".pv" 0.75556;
createNode transform -n "curve94" -p "follicle94";
createNode nurbsCurve -n "curve94Shape" -p "curve94";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.032231 -0.086487 -0.10689
		-0.076929 -0.33535 -0.25513
		-0.10071 -0.77494 -0.33401
		-0.071632 -1.4297 -0.23756
		-0.017494 -2.0913 -0.058018
		0.05965 -2.6825 0.19782
		;
createNode transform -n "follicle95" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.30564 1.6837 -0.75221 ;
createNode follicle -n "follicle95Shape" -p "follicle95";
	setAttr ".pu" 0.68857;
	setAttr ".pv" 0.69841;
createNode transform -n "curve95" -p "follicle95";
createNode nurbsCurve -n "curve95Shape" -p "curve95";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.033173 -0.093321 -0.081641
		-0.072758 -0.33725 -0.17906
		-0.0832 -0.74194 -0.20476
		-0.03796 -1.3373 -0.093423
		0.02992 -1.9625 0.073636
		0.12193 -2.5283 0.30007
		;
createNode transform -n "follicle96" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.24777 1.5294 -0.86847 ;
createNode follicle -n "follicle96Shape" -p "follicle96";
	setAttr ".pu" 0.70577;
	setAttr ".pv" 0.64127;
createNode transform -n "curve96" -p "follicle96";
createNode nurbsCurve -n "curve96Shape" -p "curve96";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.018049 -0.094967 -0.063266
		-0.034738 -0.32519 -0.12176
		-0.029962 -0.68864 -0.10502
		0.0064784 -1.2889 0.022708
		0.053257 -1.8951 0.18667
		0.11388 -2.4524 0.39915
		;
createNode transform -n "follicle97" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.40642 1.3612 -0.87555 ;
createNode follicle -n "follicle97Shape" -p "follicle97";
	setAttr ".pu" 0.68083;
	setAttr ".pv" 0.58413;
createNode transform -n "curve97" -p "follicle97";
createNode nurbsCurve -n "curve97Shape" -p "curve97";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.019228 -0.092067 -0.041422
		-0.029028 -0.30136 -0.062535
		-0.0069756 -0.619 -0.015027
		0.051447 -1.0957 0.11083
		0.11805 -1.6521 0.25431
		0.20094 -2.1694 0.43287
		;
createNode transform -n "follicle98" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.046215 2.0738 -0.22263 ;
createNode follicle -n "follicle98Shape" -p "follicle98";
	setAttr ".pu" 0.71742;
	setAttr ".pv" 0.92698;
createNode transform -n "curve98" -p "follicle98";
createNode nurbsCurve -n "curve98Shape" -p "curve98";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.036001 -0.032 -0.17343
		-0.1005 -0.23208 -0.48415
		-0.15994 -0.72239 -0.7705
		-0.15951 -1.4701 -0.76841
		-0.12035 -2.2274 -0.57978
		-0.052979 -2.8797 -0.25522
		;
createNode transform -n "follicle99" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.028889 2.0176 -0.39655 ;
createNode follicle -n "follicle99Shape" -p "follicle99";
	setAttr ".pu" 0.73843;
	setAttr ".pv" 0.86984;
createNode transform -n "curve99" -p "follicle99";
createNode nurbsCurve -n "curve99Shape" -p "curve99";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.011439 -0.055845 -0.15703
		-0.030549 -0.28351 -0.41934
		-0.046249 -0.76735 -0.63486
		-0.043228 -1.4763 -0.59339
		-0.02915 -2.1985 -0.40014
		-0.0065707 -2.8273 -0.090195
		;
createNode transform -n "follicle100" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.1082 1.9318 -0.5444 ;
createNode follicle -n "follicle100Shape" -p "follicle100";
	setAttr ".pu" 0.71878;
	setAttr ".pv" 0.8127;
createNode transform -n "curve100" -p "follicle100";
createNode nurbsCurve -n "curve100Shape" -p "curve100";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.02635 -0.074048 -0.13258
		-0.066918 -0.3178 -0.3367
		-0.095297 -0.78428 -0.47949
		-0.080773 -1.4322 -0.40641
		-0.04334 -2.1149 -0.21806
		0.013063 -2.7159 0.065727
		;
createNode transform -n "follicle101" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.035369 1.8193 -0.69376 ;
createNode follicle -n "follicle101Shape" -p "follicle101";
	setAttr ".pu" 0.74189;
	setAttr ".pv" 0.75556;
createNode transform -n "curve101" -p "follicle101";
createNode nurbsCurve -n "curve101Shape" -p "curve101";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.0056844 -0.086487 -0.1115
		-0.013568 -0.33535 -0.26613
		-0.017762 -0.77494 -0.34841
		-0.012633 -1.4067 -0.2478
		-0.0030854 -2.0625 -0.060519
		0.01052 -2.6479 0.20635
		;
createNode transform -n "follicle102" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.15618 1.6837 -0.79678 ;
createNode follicle -n "follicle102Shape" -p "follicle102";
	setAttr ".pu" 0.71919;
	setAttr ".pv" 0.69841;
createNode transform -n "curve102" -p "follicle102";
createNode nurbsCurve -n "curve102Shape" -p "curve102";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.016951 -0.093321 -0.086478
		-0.037178 -0.33725 -0.18967
		-0.042513 -0.74194 -0.21689
		-0.019397 -1.3572 -0.098958
		0.015288 -1.9874 0.077998
		0.062302 -2.5582 0.31785
		;
createNode transform -n "follicle103" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.04633 1.5294 -0.90193 ;
createNode follicle -n "follicle103Shape" -p "follicle103";
	setAttr ".pu" 0.74183;
	setAttr ".pv" 0.64127;
createNode transform -n "curve103" -p "follicle103";
createNode nurbsCurve -n "curve103Shape" -p "curve103";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.003375 -0.094967 -0.065703
		-0.0064957 -0.32519 -0.12645
		-0.0056025 -0.68864 -0.10907
		0.0012114 -1.2348 0.023583
		0.0099585 -1.8275 0.19387
		0.021294 -2.3713 0.41453
		;
createNode transform -n "follicle104" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" -0.15628 1.3612 -0.95254 ;
createNode follicle -n "follicle104Shape" -p "follicle104";
	setAttr ".pu" 0.72412;
	setAttr ".pv" 0.58413;
createNode transform -n "curve104" -p "follicle104";
createNode nurbsCurve -n "curve104Shape" -p "curve104";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		-0.0073937 -0.092067 -0.045065
		-0.011162 -0.30136 -0.068035
		-0.0026823 -0.619 -0.016349
		0.019783 -1.129 0.12058
		0.045393 -1.6937 0.27667
		0.077266 -2.2194 0.47094
		;
createNode transform -n "follicle105" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.008139 2.0738 -0.22723 ;
createNode follicle -n "follicle105Shape" -p "follicle105";
	setAttr ".pu" 0.7557;
	setAttr ".pv" 0.92698;
createNode transform -n "curve105" -p "follicle105";
createNode nurbsCurve -n "curve105Shape" -p "curve105";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.0063403 -0.032 -0.17701
		0.0177 -0.23208 -0.49416
		0.028168 -0.72239 -0.78642
		0.028092 -1.5078 -0.78429
		0.021196 -2.2745 -0.59176
		0.0093303 -2.9363 -0.26049
		;
createNode transform -n "follicle106" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.045015 2.0176 -0.39505 ;
createNode follicle -n "follicle106Shape" -p "follicle106";
	setAttr ".pu" 0.76806;
	setAttr ".pv" 0.86984;
createNode transform -n "curve106" -p "follicle106";
createNode nurbsCurve -n "curve106Shape" -p "curve106";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.017825 -0.055845 -0.15643
		0.047602 -0.28351 -0.41775
		0.072067 -0.76735 -0.63245
		0.067359 -1.5004 -0.59114
		0.045423 -2.2286 -0.39862
		0.010239 -2.8634 -0.089853
		;
createNode transform -n "follicle107" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.0068418 1.9318 -0.55501 ;
createNode follicle -n "follicle107Shape" -p "follicle107";
	setAttr ".pu" 0.75196;
	setAttr ".pv" 0.8127;
createNode transform -n "curve107" -p "follicle107";
createNode nurbsCurve -n "curve107Shape" -p "curve107";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.0016662 -0.074048 -0.13516
		0.0042315 -0.3178 -0.34326
		0.006026 -0.78428 -0.48883
		0.0051076 -1.4153 -0.41433
		0.0027405 -2.0937 -0.22231
		-0.00082602 -2.6904 0.067007
		;
createNode transform -n "follicle108" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.11478 1.8193 -0.68511 ;
createNode follicle -n "follicle108Shape" -p "follicle108";
	setAttr ".pu" 0.77642;
	setAttr ".pv" 0.75556;
createNode transform -n "curve108" -p "follicle108";
createNode nurbsCurve -n "curve108Shape" -p "curve108";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.018448 -0.086487 -0.11011
		0.044032 -0.33535 -0.26281
		0.057645 -0.77494 -0.34407
		0.041 -1.3825 -0.24471
		0.010013 -2.0323 -0.059765
		-0.034141 -2.6116 0.20378
		;
createNode transform -n "follicle109" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.025877 1.6837 -0.81153 ;
createNode follicle -n "follicle109Shape" -p "follicle109";
	setAttr ".pu" 0.75507;
	setAttr ".pv" 0.69841;
createNode transform -n "curve109" -p "follicle109";
createNode nurbsCurve -n "curve109Shape" -p "curve109";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.0028085 -0.093321 -0.088079
		0.0061599 -0.33725 -0.19318
		0.0070439 -0.74194 -0.22091
		0.0032138 -1.3761 -0.10079
		-0.0025331 -2.0111 0.079442
		-0.010323 -2.5866 0.32373
		;
createNode transform -n "follicle110" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.13466 1.5294 -0.89303 ;
createNode follicle -n "follicle110Shape" -p "follicle110";
	setAttr ".pu" 0.77382;
	setAttr ".pv" 0.64127;
createNode transform -n "curve110" -p "follicle110";
createNode nurbsCurve -n "curve110Shape" -p "curve110";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.0098095 -0.094967 -0.065055
		0.01888 -0.32519 -0.12521
		0.016284 -0.68864 -0.10799
		-0.0035209 -1.2222 0.02335
		-0.028944 -1.8117 0.19195
		-0.06189 -2.3524 0.41044
		;
createNode transform -n "follicle111" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.033677 1.3612 -0.96469 ;
createNode follicle -n "follicle111Shape" -p "follicle111";
	setAttr ".pu" 0.75555;
	setAttr ".pv" 0.58413;
createNode transform -n "curve111" -p "follicle111";
createNode nurbsCurve -n "curve111Shape" -p "curve111";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.0015933 -0.092067 -0.04564
		0.0024053 -0.30136 -0.068902
		0.00057801 -0.619 -0.016557
		-0.004263 -1.1362 0.12212
		-0.0097816 -1.7027 0.2802
		-0.01665 -2.2301 0.47695
		;
createNode transform -n "follicle112" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.062225 2.0738 -0.2187 ;
createNode follicle -n "follicle112Shape" -p "follicle112";
	setAttr ".pu" 0.79412;
	setAttr ".pv" 0.92698;
createNode transform -n "curve112" -p "follicle112";
createNode nurbsCurve -n "curve112Shape" -p "curve112";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.048473 -0.032 -0.17037
		0.13532 -0.23208 -0.4756
		0.21535 -0.72239 -0.75689
		0.21477 -1.4522 -0.75484
		0.16205 -2.205 -0.56954
		0.071332 -2.8529 -0.25071
		;
createNode transform -n "follicle113" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.14538 2.0176 -0.37007 ;
createNode follicle -n "follicle113Shape" -p "follicle113";
	setAttr ".pu" 0.80957;
	setAttr ".pv" 0.86984;
createNode transform -n "curve113" -p "follicle113";
createNode nurbsCurve -n "curve113Shape" -p "curve113";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.057567 -0.055845 -0.14654
		0.15373 -0.28351 -0.39134
		0.23274 -0.76735 -0.59247
		0.21754 -1.4749 -0.55377
		0.1467 -2.1967 -0.37342
		0.033066 -2.8251 -0.084172
		;
createNode transform -n "follicle114" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.13358 1.9318 -0.53874 ;
createNode follicle -n "follicle114Shape" -p "follicle114";
	setAttr ".pu" 0.78868;
	setAttr ".pv" 0.8127;
createNode transform -n "curve114" -p "follicle114";
createNode nurbsCurve -n "curve114Shape" -p "curve114";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.032531 -0.074048 -0.1312
		0.082613 -0.3178 -0.3332
		0.11765 -0.78428 -0.4745
		0.099718 -1.5177 -0.40218
		0.053505 -2.2218 -0.21579
		-0.016127 -2.8441 0.065043
		;
createNode transform -n "follicle115" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.2517 1.8193 -0.64745 ;
createNode follicle -n "follicle115Shape" -p "follicle115";
	setAttr ".pu" 0.80901;
	setAttr ".pv" 0.75556;
createNode transform -n "curve115" -p "follicle115";
createNode nurbsCurve -n "curve115Shape" -p "curve115";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.040453 -0.086487 -0.10406
		0.096554 -0.33535 -0.24837
		0.12641 -0.77494 -0.32515
		0.089906 -1.4344 -0.23126
		0.021957 -2.0972 -0.05648
		-0.074866 -2.6895 0.19258
		;
createNode transform -n "follicle116" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.22092 1.6837 -0.78131 ;
createNode follicle -n "follicle116Shape" -p "follicle116";
	setAttr ".pu" 0.79386;
	setAttr ".pv" 0.69841;
createNode transform -n "curve116" -p "follicle116";
createNode nurbsCurve -n "curve116Shape" -p "curve116";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.023977 -0.093321 -0.084799
		0.05259 -0.33725 -0.18599
		0.060136 -0.74194 -0.21268
		0.027438 -1.4011 -0.097036
		-0.021626 -2.0423 0.076484
		-0.088129 -2.6241 0.31168
		;
createNode transform -n "follicle117" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.32358 1.5294 -0.84316 ;
createNode follicle -n "follicle117Shape" -p "follicle117";
	setAttr ".pu" 0.80832;
	setAttr ".pv" 0.64127;
createNode transform -n "curve117" -p "follicle117";
createNode nurbsCurve -n "curve117Shape" -p "curve117";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.023572 -0.094967 -0.061422
		0.045367 -0.32519 -0.11821
		0.039129 -0.68864 -0.10196
		-0.0084607 -1.2604 0.022046
		-0.069553 -1.8595 0.18123
		-0.14872 -2.4097 0.38752
		;
createNode transform -n "follicle118" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.24669 1.3612 -0.93322 ;
createNode follicle -n "follicle118Shape" -p "follicle118";
	setAttr ".pu" 0.79113;
	setAttr ".pv" 0.58413;
createNode transform -n "curve118" -p "follicle118";
createNode nurbsCurve -n "curve118Shape" -p "curve118";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.011671 -0.092067 -0.044151
		0.01762 -0.30136 -0.066655
		0.0042341 -0.619 -0.016017
		-0.031228 -1.1304 0.11813
		-0.071653 -1.6955 0.27106
		-0.12197 -2.2215 0.46139
		;
createNode transform -n "follicle119" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.1081 2.0738 -0.20004 ;
createNode follicle -n "follicle119Shape" -p "follicle119";
	setAttr ".pu" 0.82885;
	setAttr ".pv" 0.92698;
createNode transform -n "curve119" -p "follicle119";
createNode nurbsCurve -n "curve119Shape" -p "curve119";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.084209 -0.032 -0.15583
		0.23508 -0.23208 -0.43502
		0.37411 -0.72239 -0.69231
		0.3731 -1.4983 -0.69043
		0.28151 -2.2627 -0.52095
		0.12392 -2.9221 -0.22932
		;
createNode transform -n "follicle120" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.22349 2.0176 -0.32885 ;
createNode follicle -n "follicle120Shape" -p "follicle120";
	setAttr ".pu" 0.845;
	setAttr ".pv" 0.86984;
createNode transform -n "curve120" -p "follicle120";
createNode nurbsCurve -n "curve120Shape" -p "curve120";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.088495 -0.055845 -0.13022
		0.23633 -0.28351 -0.34775
		0.35779 -0.76735 -0.52647
		0.33442 -1.5055 -0.49208
		0.22551 -2.2349 -0.33183
		0.050831 -2.871 -0.074797
		;
createNode transform -n "follicle121" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.27202 1.9318 -0.48383 ;
createNode follicle -n "follicle121Shape" -p "follicle121";
	setAttr ".pu" 0.83152;
	setAttr ".pv" 0.8127;
createNode transform -n "curve121" -p "follicle121";
createNode nurbsCurve -n "curve121Shape" -p "curve121";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.066246 -0.074048 -0.11783
		0.16824 -0.3178 -0.29923
		0.23958 -0.78428 -0.42613
		0.20307 -1.508 -0.36119
		0.10896 -2.2096 -0.1938
		-0.032841 -2.8295 0.058413
		;
createNode transform -n "follicle122" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.40362 1.8193 -0.56536 ;
createNode follicle -n "follicle122Shape" -p "follicle122";
	setAttr ".pu" 0.84868;
	setAttr ".pv" 0.75556;
createNode transform -n "curve122" -p "follicle122";
createNode nurbsCurve -n "curve122Shape" -p "curve122";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.064869 -0.086487 -0.090864
		0.15483 -0.33535 -0.21688
		0.2027 -0.77494 -0.28393
		0.14417 -1.4851 -0.20194
		0.03521 -2.1606 -0.049319
		-0.12005 -2.7656 0.16816
		;
createNode transform -n "follicle123" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.36502 1.6837 -0.72526 ;
createNode follicle -n "follicle123Shape" -p "follicle123";
	setAttr ".pu" 0.82421;
	setAttr ".pv" 0.69841;
createNode transform -n "curve123" -p "follicle123";
createNode nurbsCurve -n "curve123Shape" -p "curve123";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.039617 -0.093321 -0.078716
		0.086892 -0.33725 -0.17265
		0.099361 -0.74194 -0.19742
		0.045334 -1.354 -0.090076
		-0.035732 -1.9835 0.070998
		-0.14561 -2.5535 0.28932
		;
createNode transform -n "follicle124" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.52805 1.5294 -0.73266 ;
createNode follicle -n "follicle124Shape" -p "follicle124";
	setAttr ".pu" 0.84939;
	setAttr ".pv" 0.64127;
createNode transform -n "curve124" -p "follicle124";
createNode nurbsCurve -n "curve124Shape" -p "curve124";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.038467 -0.094967 -0.053373
		0.074034 -0.32519 -0.10272
		0.063854 -0.68864 -0.088597
		-0.013807 -1.2907 0.019157
		-0.1135 -1.8974 0.15748
		-0.24269 -2.4552 0.33674
		;
createNode transform -n "follicle125" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.42683 1.3612 -0.86578 ;
createNode follicle -n "follicle125Shape" -p "follicle125";
	setAttr ".pu" 0.8229;
	setAttr ".pv" 0.58413;
createNode transform -n "curve125" -p "follicle125";
createNode nurbsCurve -n "curve125Shape" -p "curve125";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.020193 -0.092067 -0.04096
		0.030486 -0.30136 -0.061838
		0.0073259 -0.619 -0.01486
		-0.05403 -1.0783 0.10959
		-0.12397 -1.6304 0.25147
		-0.21103 -2.1434 0.42805
		;
createNode transform -n "follicle126" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.147 2.0738 -0.17348 ;
createNode follicle -n "follicle126Shape" -p "follicle126";
	setAttr ".pu" 0.86188;
	setAttr ".pv" 0.92698;
createNode transform -n "curve126" -p "follicle126";
createNode nurbsCurve -n "curve126Shape" -p "curve126";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.11451 -0.032 -0.13514
		0.31967 -0.23208 -0.37725
		0.50873 -0.72239 -0.60037
		0.50735 -1.4477 -0.59874
		0.38281 -2.1994 -0.45176
		0.16851 -2.8461 -0.19887
		;
createNode transform -n "follicle127" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.28567 2.0176 -0.27656 ;
createNode follicle -n "follicle127Shape" -p "follicle127";
	setAttr ".pu" 0.87758;
	setAttr ".pv" 0.86984;
createNode transform -n "curve127" -p "follicle127";
createNode nurbsCurve -n "curve127Shape" -p "curve127";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.11312 -0.055845 -0.10951
		0.30208 -0.28351 -0.29245
		0.45734 -0.76735 -0.44275
		0.42746 -1.4515 -0.41383
		0.28825 -2.1674 -0.27906
		0.064974 -2.79 -0.062902
		;
createNode transform -n "follicle128" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.36527 1.9318 -0.41792 ;
createNode follicle -n "follicle128Shape" -p "follicle128";
	setAttr ".pu" 0.86432;
	setAttr ".pv" 0.8127;
createNode transform -n "curve128" -p "follicle128";
createNode nurbsCurve -n "curve128Shape" -p "curve128";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.088956 -0.074048 -0.10178
		0.22591 -0.3178 -0.25848
		0.32171 -0.78428 -0.36809
		0.27268 -1.5193 -0.31199
		0.14631 -2.2238 -0.1674
		-0.044099 -2.8464 0.050457
		;
createNode transform -n "follicle129" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.51995 1.8193 -0.46066 ;
createNode follicle -n "follicle129Shape" -p "follicle129";
	setAttr ".pu" 0.88461;
	setAttr ".pv" 0.75556;
createNode transform -n "curve129" -p "follicle129";
createNode nurbsCurve -n "curve129Shape" -p "curve129";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.083564 -0.086487 -0.074036
		0.19945 -0.33535 -0.17671
		0.26112 -0.77494 -0.23135
		0.18572 -1.3801 -0.16454
		0.045357 -2.0293 -0.040185
		-0.15465 -2.6081 0.13702
		;
createNode transform -n "follicle130" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.53624 1.6837 -0.60967 ;
createNode follicle -n "follicle130Shape" -p "follicle130";
	setAttr ".pu" 0.86482;
	setAttr ".pv" 0.69841;
createNode transform -n "curve130" -p "follicle130";
createNode nurbsCurve -n "curve130Shape" -p "curve130";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.058201 -0.093321 -0.06617
		0.12765 -0.33725 -0.14513
		0.14597 -0.74194 -0.16596
		0.066599 -1.3675 -0.075719
		-0.052494 -2.0003 0.059682
		-0.21392 -2.5736 0.24321
		;
createNode transform -n "follicle131" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.64472 1.5294 -0.63243 ;
createNode follicle -n "follicle131Shape" -p "follicle131";
	setAttr ".pu" 0.87653;
	setAttr ".pv" 0.64127;
createNode transform -n "curve131" -p "follicle131";
createNode nurbsCurve -n "curve131Shape" -p "curve131";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.046966 -0.094967 -0.046071
		0.090392 -0.32519 -0.088668
		0.077963 -0.68864 -0.076476
		-0.016857 -1.2964 0.016536
		-0.13858 -1.9046 0.13594
		-0.29632 -2.4638 0.29067
		;
createNode transform -n "follicle132" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.64969 1.3612 -0.71391 ;
createNode follicle -n "follicle132Shape" -p "follicle132";
	setAttr ".pu" 0.86751;
	setAttr ".pv" 0.58413;
createNode transform -n "curve132" -p "follicle132";
createNode nurbsCurve -n "curve132Shape" -p "curve132";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.030737 -0.092067 -0.033775
		0.046403 -0.30136 -0.05099
		0.011151 -0.619 -0.012253
		-0.082241 -1.0914 0.09037
		-0.1887 -1.6467 0.20736
		-0.32121 -2.163 0.35296
		;
createNode transform -n "follicle133" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.18649 2.0738 -0.13009 ;
createNode follicle -n "follicle133Shape" -p "follicle133";
	setAttr ".pu" 0.90306;
	setAttr ".pv" 0.92698;
createNode transform -n "curve133" -p "follicle133";
createNode nurbsCurve -n "curve133Shape" -p "curve133";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.14528 -0.032 -0.10134
		0.40556 -0.23208 -0.28289
		0.64542 -0.72239 -0.45021
		0.64367 -1.4911 -0.44899
		0.48566 -2.2537 -0.33877
		0.21379 -2.9113 -0.14913
		;
createNode transform -n "follicle134" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.34342 2.0176 -0.20038 ;
createNode follicle -n "follicle134Shape" -p "follicle134";
	setAttr ".pu" 0.91593;
	setAttr ".pv" 0.86984;
createNode transform -n "curve134" -p "follicle134";
createNode nurbsCurve -n "curve134Shape" -p "curve134";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.13599 -0.055845 -0.079347
		0.36315 -0.28351 -0.2119
		0.54979 -0.76735 -0.3208
		0.51388 -1.5737 -0.29985
		0.34653 -2.3202 -0.2022
		0.07811 -2.9734 -0.045577
		;
createNode transform -n "follicle135" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.45266 1.9318 -0.32122 ;
createNode follicle -n "follicle135Shape" -p "follicle135";
	setAttr ".pu" 0.90178;
	setAttr ".pv" 0.8127;
createNode transform -n "curve135" -p "follicle135";
createNode nurbsCurve -n "curve135Shape" -p "curve135";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.11024 -0.074048 -0.078228
		0.27996 -0.3178 -0.19867
		0.39868 -0.78428 -0.28292
		0.33792 -1.4363 -0.2398
		0.18132 -2.12 -0.12867
		-0.05465 -2.7219 0.038781
		;
createNode transform -n "follicle136" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.59867 1.8193 -0.35234 ;
createNode follicle -n "follicle136Shape" -p "follicle136";
	setAttr ".pu" 0.91534;
	setAttr ".pv" 0.75556;
createNode transform -n "curve136" -p "follicle136";
createNode nurbsCurve -n "curve136Shape" -p "curve136";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.096216 -0.086487 -0.056627
		0.22965 -0.33535 -0.13516
		0.30066 -0.77494 -0.17695
		0.21384 -1.4282 -0.12585
		0.052224 -2.0895 -0.030736
		-0.17807 -2.6803 0.1048
		;
createNode transform -n "follicle137" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.64619 1.6837 -0.49161 ;
createNode follicle -n "follicle137Shape" -p "follicle137";
	setAttr ".pu" 0.89649;
	setAttr ".pv" 0.69841;
createNode transform -n "curve137" -p "follicle137";
createNode nurbsCurve -n "curve137Shape" -p "curve137";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.070134 -0.093321 -0.053357
		0.15383 -0.33725 -0.11703
		0.1759 -0.74194 -0.13382
		0.080255 -1.3055 -0.061057
		-0.063257 -1.9228 0.048125
		-0.25778 -2.4807 0.19611
		;
createNode transform -n "follicle138" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.77482 1.5294 -0.46398 ;
createNode follicle -n "follicle138Shape" -p "follicle138";
	setAttr ".pu" 0.91413;
	setAttr ".pv" 0.64127;
createNode transform -n "curve138" -p "follicle138";
createNode nurbsCurve -n "curve138Shape" -p "curve138";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.056444 -0.094967 -0.0338
		0.10863 -0.32519 -0.065052
		0.093695 -0.68864 -0.056107
		-0.020259 -1.275 0.012132
		-0.16654 -1.8778 0.099731
		-0.35611 -2.4316 0.21325
		;
createNode transform -n "follicle139" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.75547 1.3612 -0.60085 ;
createNode follicle -n "follicle139Shape" -p "follicle139";
	setAttr ".pu" 0.89307;
	setAttr ".pv" 0.58413;
createNode transform -n "curve139" -p "follicle139";
createNode nurbsCurve -n "curve139Shape" -p "curve139";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.035742 -0.092067 -0.028426
		0.053959 -0.30136 -0.042915
		0.012967 -0.619 -0.010313
		-0.095632 -1.136 0.076059
		-0.21943 -1.7025 0.17452
		-0.37351 -2.2299 0.29706
		;
createNode transform -n "follicle140" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.2077 2.0738 -0.092539 ;
createNode follicle -n "follicle140Shape" -p "follicle140";
	setAttr ".pu" 0.93329;
	setAttr ".pv" 0.92698;
createNode transform -n "curve140" -p "follicle140";
createNode nurbsCurve -n "curve140Shape" -p "curve140";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.1618 -0.032 -0.072088
		0.45167 -0.23208 -0.20124
		0.71881 -0.72239 -0.32026
		0.71686 -1.4404 -0.3194
		0.54089 -2.1903 -0.24099
		0.2381 -2.8353 -0.10608
		;
createNode transform -n "follicle141" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.37813 2.0176 -0.12291 ;
createNode follicle -n "follicle141Shape" -p "follicle141";
	setAttr ".pu" 0.94998;
	setAttr ".pv" 0.86984;
createNode transform -n "curve141" -p "follicle141";
createNode nurbsCurve -n "curve141Shape" -p "curve141";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.14973 -0.055845 -0.048671
		0.39986 -0.28351 -0.12998
		0.60536 -0.76735 -0.19678
		0.56582 -1.5249 -0.18392
		0.38155 -2.2592 -0.12403
		0.086005 -2.9002 -0.027956
		;
createNode transform -n "follicle142" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.50809 1.9318 -0.22344 ;
createNode follicle -n "follicle142Shape" -p "follicle142";
	setAttr ".pu" 0.93406;
	setAttr ".pv" 0.8127;
createNode transform -n "curve142" -p "follicle142";
createNode nurbsCurve -n "curve142Shape" -p "curve142";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.12374 -0.074048 -0.054416
		0.31424 -0.3178 -0.13819
		0.4475 -0.78428 -0.1968
		0.3793 -1.4233 -0.16681
		0.20352 -2.1038 -0.089501
		-0.061342 -2.7025 0.026976
		;
createNode transform -n "follicle143" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.66944 1.8193 -0.18548 ;
createNode follicle -n "follicle143Shape" -p "follicle143";
	setAttr ".pu" 0.95698;
	setAttr ".pv" 0.75556;
createNode transform -n "curve143" -p "follicle143";
createNode nurbsCurve -n "curve143Shape" -p "curve143";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.10759 -0.086487 -0.029809
		0.2568 -0.33535 -0.07115
		0.3362 -0.77494 -0.093148
		0.23912 -1.4646 -0.06625
		0.058398 -2.1349 -0.01618
		-0.19912 -2.7348 0.055168
		;
createNode transform -n "follicle144" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.75299 1.6837 -0.30371 ;
createNode follicle -n "follicle144Shape" -p "follicle144";
	setAttr ".pu" 0.93898;
	setAttr ".pv" 0.69841;
createNode transform -n "curve144" -p "follicle144";
createNode nurbsCurve -n "curve144Shape" -p "curve144";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.081726 -0.093321 -0.032964
		0.17925 -0.33725 -0.072299
		0.20497 -0.74194 -0.082674
		0.09352 -1.2934 -0.037721
		-0.073713 -1.9077 0.029731
		-0.30038 -2.4625 0.12116
		;
createNode transform -n "follicle145" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.85764 1.5294 -0.283 ;
createNode follicle -n "follicle145Shape" -p "follicle145";
	setAttr ".pu" 0.94927;
	setAttr ".pv" 0.64127;
createNode transform -n "curve145" -p "follicle145";
createNode nurbsCurve -n "curve145Shape" -p "curve145";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.062477 -0.094967 -0.020615
		0.12024 -0.32519 -0.039677
		0.10371 -0.68864 -0.034221
		-0.022425 -1.184 0.0073994
		-0.18435 -1.764 0.060829
		-0.39418 -2.2951 0.13007
		;
createNode transform -n "follicle146" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.89044 1.3612 -0.37266 ;
createNode follicle -n "follicle146Shape" -p "follicle146";
	setAttr ".pu" 0.93692;
	setAttr ".pv" 0.58413;
createNode transform -n "curve146" -p "follicle146";
createNode nurbsCurve -n "curve146Shape" -p "curve146";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.042127 -0.092067 -0.01763
		0.063599 -0.30136 -0.026617
		0.015283 -0.619 -0.0063961
		-0.11272 -1.0982 0.047173
		-0.25863 -1.6552 0.10824
		-0.44024 -2.1731 0.18424
		;
createNode transform -n "follicle147" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.22211 2.0738 -0.048661 ;
createNode follicle -n "follicle147Shape" -p "follicle147";
	setAttr ".pu" 0.96567;
	setAttr ".pv" 0.92698;
createNode transform -n "curve147" -p "follicle147";
createNode nurbsCurve -n "curve147Shape" -p "curve147";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.17302 -0.032 -0.037907
		0.48302 -0.23208 -0.10582
		0.76869 -0.72239 -0.16841
		0.76661 -1.4943 -0.16795
		0.57842 -2.2577 -0.12672
		0.25462 -2.9161 -0.055784
		;
createNode transform -n "follicle148" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.39709 2.0176 -0.020207 ;
createNode follicle -n "follicle148Shape" -p "follicle148";
	setAttr ".pu" 0.99191;
	setAttr ".pv" 0.86984;
createNode transform -n "curve148" -p "follicle148";
createNode nurbsCurve -n "curve148Shape" -p "curve148";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.15724 -0.055845 -0.0080015
		0.41991 -0.28351 -0.021368
		0.63572 -0.76735 -0.03235
		0.5942 -1.551 -0.030237
		0.40069 -2.2917 -0.02039
		0.090317 -2.9392 -0.004596
		;
createNode transform -n "follicle149" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.5432 1.9318 -0.11407 ;
createNode follicle -n "follicle149Shape" -p "follicle149";
	setAttr ".pu" 0.96706;
	setAttr ".pv" 0.8127;
createNode transform -n "curve149" -p "follicle149";
createNode nurbsCurve -n "curve149Shape" -p "curve149";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.13229 -0.074048 -0.02778
		0.33596 -0.3178 -0.07055
		0.47843 -0.78428 -0.10047
		0.40551 -1.4347 -0.085157
		0.21758 -2.118 -0.045692
		-0.065582 -2.7195 0.013772
		;
createNode transform -n "follicle150" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.69378 1.8193 -0.034941 ;
createNode follicle -n "follicle150Shape" -p "follicle150";
	setAttr ".pu" 0.99199;
	setAttr ".pv" 0.75556;
createNode transform -n "curve150" -p "follicle150";
createNode nurbsCurve -n "curve150Shape" -p "curve150";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.1115 -0.086487 -0.0056157
		0.26614 -0.33535 -0.013404
		0.34842 -0.77494 -0.017548
		0.24781 -1.4356 -0.012481
		0.060521 -2.0986 -0.0030481
		-0.20636 -2.6913 0.010393
		;
createNode transform -n "follicle151" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.79922 1.6837 -0.14316 ;
createNode follicle -n "follicle151Shape" -p "follicle151";
	setAttr ".pu" 0.97179;
	setAttr ".pv" 0.69841;
createNode transform -n "curve151" -p "follicle151";
createNode nurbsCurve -n "curve151Shape" -p "curve151";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.086743 -0.093321 -0.015538
		0.19025 -0.33725 -0.03408
		0.21756 -0.74194 -0.03897
		0.099261 -1.2914 -0.01778
		-0.078237 -1.9051 0.014014
		-0.31882 -2.4595 0.05711
		;
createNode transform -n "follicle152" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.89783 1.5294 -0.097641 ;
createNode follicle -n "follicle152Shape" -p "follicle152";
	setAttr ".pu" 0.98276;
	setAttr ".pv" 0.64127;
createNode transform -n "curve152" -p "follicle152";
createNode nurbsCurve -n "curve152Shape" -p "curve152";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.065404 -0.094967 -0.0071129
		0.12588 -0.32519 -0.01369
		0.10857 -0.68864 -0.011807
		-0.023475 -1.2705 0.002553
		-0.19298 -1.8721 0.020988
		-0.41265 -2.4249 0.044877
		;
createNode transform -n "follicle153" -p "hairSystem1Follicles";
	setAttr ".t" -type "double3" 0.94684 1.3612 -0.18776 ;
createNode follicle -n "follicle153Shape" -p "follicle153";
	setAttr ".pu" 0.96884;
	setAttr ".pv" 0.58413;
createNode transform -n "curve153" -p "follicle153";
createNode nurbsCurve -n "curve153Shape" -p "curve153";
	setAttr ".cc" -type "nurbsCurve" 
		3 4 0 no 3
		9 0 0 0 1 2 3 4 4 4
		7
		0 0 0
		0.044795 -0.092067 -0.0088832
		0.067627 -0.30136 -0.013411
		0.016251 -0.619 -0.0032227
		-0.11986 -1.0718 0.023768
		-0.27501 -1.6222 0.054537
		-0.46812 -2.1335 0.092832
		;
createNode FurDescription -n "FurDescription1";
	setAttr ".d" 20000;
	setAttr ".dl" 0.15;
	setAttr ".dbw" 0.01;
	setAttr ".dtw" 0.002;
	setAttr ".dbc" -type "float3" 0.3 0.2 0.1 ;
	setAttr ".di" 0.6;
createNode transform -n "FurFeedback1";
createNode FurFeedback -n "FurFeedbackShape1" -p "FurFeedback1";
createNode transform -n "key";
	setAttr ".r" -type "double3" -50 35 0 ;
createNode directionalLight -n "keyShape" -p "key";
	setAttr ".in" 1.1;
createNode transform -n "fill";
createNode ambientLight -n "fillShape" -p "fill";
	setAttr ".in" 0.2;
select -ne :defaultResolution;
	setAttr ".w" 480;
	setAttr ".h" 360;
connectAttr "polySphere1.out" "headShape.i";
connectAttr "skin.oc" "skinSG.ss";
connectAttr "headShape.iog" "skinSG.dsm" -na;
connectAttr "headShape.w" "FurFeedbackShape1.imsh";
connectAttr "FurDescription1.dl" "FurFeedbackShape1.dl";
connectAttr "curve1Shape.ws" "follicle1Shape.sp";
connectAttr "headShape.o" "follicle1Shape.inm";
connectAttr "follicle1Shape.oha" "hairSystemShape1.ih[0]";
connectAttr "hairSystemShape1.oh[0]" "follicle1Shape.crp";
connectAttr "curve2Shape.ws" "follicle2Shape.sp";
connectAttr "headShape.o" "follicle2Shape.inm";
connectAttr "follicle2Shape.oha" "hairSystemShape1.ih[1]";
connectAttr "hairSystemShape1.oh[1]" "follicle2Shape.crp";
connectAttr "curve3Shape.ws" "follicle3Shape.sp";
connectAttr "headShape.o" "follicle3Shape.inm";
connectAttr "follicle3Shape.oha" "hairSystemShape1.ih[2]";
connectAttr "hairSystemShape1.oh[2]" "follicle3Shape.crp";
connectAttr "curve4Shape.ws" "follicle4Shape.sp";
connectAttr "headShape.o" "follicle4Shape.inm";
connectAttr "follicle4Shape.oha" "hairSystemShape1.ih[3]";
connectAttr "hairSystemShape1.oh[3]" "follicle4Shape.crp";
connectAttr "curve5Shape.ws" "follicle5Shape.sp";
connectAttr "headShape.o" "follicle5Shape.inm";
connectAttr "follicle5Shape.oha" "hairSystemShape1.ih[4]";
connectAttr "hairSystemShape1.oh[4]" "follicle5Shape.crp";
connectAttr "curve6Shape.ws" "follicle6Shape.sp";
connectAttr "headShape.o" "follicle6Shape.inm";
connectAttr "follicle6Shape.oha" "hairSystemShape1.ih[5]";
connectAttr "hairSystemShape1.oh[5]" "follicle6Shape.crp";
connectAttr "curve7Shape.ws" "follicle7Shape.sp";
connectAttr "headShape.o" "follicle7Shape.inm";
connectAttr "follicle7Shape.oha" "hairSystemShape1.ih[6]";
connectAttr "hairSystemShape1.oh[6]" "follicle7Shape.crp";
connectAttr "curve8Shape.ws" "follicle8Shape.sp";
connectAttr "headShape.o" "follicle8Shape.inm";
connectAttr "follicle8Shape.oha" "hairSystemShape1.ih[7]";
connectAttr "hairSystemShape1.oh[7]" "follicle8Shape.crp";
connectAttr "curve9Shape.ws" "follicle9Shape.sp";
connectAttr "headShape.o" "follicle9Shape.inm";
connectAttr "follicle9Shape.oha" "hairSystemShape1.ih[8]";
connectAttr "hairSystemShape1.oh[8]" "follicle9Shape.crp";
connectAttr "curve10Shape.ws" "follicle10Shape.sp";
connectAttr "headShape.o" "follicle10Shape.inm";
connectAttr "follicle10Shape.oha" "hairSystemShape1.ih[9]";
connectAttr "hairSystemShape1.oh[9]" "follicle10Shape.crp";
connectAttr "curve11Shape.ws" "follicle11Shape.sp";
connectAttr "headShape.o" "follicle11Shape.inm";
connectAttr "follicle11Shape.oha" "hairSystemShape1.ih[10]";
connectAttr "hairSystemShape1.oh[10]" "follicle11Shape.crp";
connectAttr "curve12Shape.ws" "follicle12Shape.sp";
connectAttr "headShape.o" "follicle12Shape.inm";
connectAttr "follicle12Shape.oha" "hairSystemShape1.ih[11]";
connectAttr "hairSystemShape1.oh[11]" "follicle12Shape.crp";
connectAttr "curve13Shape.ws" "follicle13Shape.sp";
connectAttr "headShape.o" "follicle13Shape.inm";
connectAttr "follicle13Shape.oha" "hairSystemShape1.ih[12]";
connectAttr "hairSystemShape1.oh[12]" "follicle13Shape.crp";
connectAttr "curve14Shape.ws" "follicle14Shape.sp";
connectAttr "headShape.o" "follicle14Shape.inm";
connectAttr "follicle14Shape.oha" "hairSystemShape1.ih[13]";
connectAttr "hairSystemShape1.oh[13]" "follicle14Shape.crp";
connectAttr "curve15Shape.ws" "follicle15Shape.sp";
connectAttr "headShape.o" "follicle15Shape.inm";
connectAttr "follicle15Shape.oha" "hairSystemShape1.ih[14]";
connectAttr "hairSystemShape1.oh[14]" "follicle15Shape.crp";
connectAttr "curve16Shape.ws" "follicle16Shape.sp";
connectAttr "headShape.o" "follicle16Shape.inm";
connectAttr "follicle16Shape.oha" "hairSystemShape1.ih[15]";
connectAttr "hairSystemShape1.oh[15]" "follicle16Shape.crp";
connectAttr "curve17Shape.ws" "follicle17Shape.sp";
connectAttr "headShape.o" "follicle17Shape.inm";
connectAttr "follicle17Shape.oha" "hairSystemShape1.ih[16]";
connectAttr "hairSystemShape1.oh[16]" "follicle17Shape.crp";
connectAttr "curve18Shape.ws" "follicle18Shape.sp";
connectAttr "headShape.o" "follicle18Shape.inm";
connectAttr "follicle18Shape.oha" "hairSystemShape1.ih[17]";
connectAttr "hairSystemShape1.oh[17]" "follicle18Shape.crp";
connectAttr "curve19Shape.ws" "follicle19Shape.sp";
connectAttr "headShape.o" "follicle19Shape.inm";
connectAttr "follicle19Shape.oha" "hairSystemShape1.ih[18]";
connectAttr "hairSystemShape1.oh[18]" "follicle19Shape.crp";
connectAttr "curve20Shape.ws" "follicle20Shape.sp";
connectAttr "headShape.o" "follicle20Shape.inm";
connectAttr "follicle20Shape.oha" "hairSystemShape1.ih[19]";
connectAttr "hairSystemShape1.oh[19]" "follicle20Shape.crp";
connectAttr "curve21Shape.ws" "follicle21Shape.sp";
connectAttr "headShape.o" "follicle21Shape.inm";
connectAttr "follicle21Shape.oha" "hairSystemShape1.ih[20]";
connectAttr "hairSystemShape1.oh[20]" "follicle21Shape.crp";
connectAttr "curve22Shape.ws" "follicle22Shape.sp";
connectAttr "headShape.o" "follicle22Shape.inm";
connectAttr "follicle22Shape.oha" "hairSystemShape1.ih[21]";
connectAttr "hairSystemShape1.oh[21]" "follicle22Shape.crp";
connectAttr "curve23Shape.ws" "follicle23Shape.sp";
connectAttr "headShape.o" "follicle23Shape.inm";
connectAttr "follicle23Shape.oha" "hairSystemShape1.ih[22]";
connectAttr "hairSystemShape1.oh[22]" "follicle23Shape.crp";
connectAttr "curve24Shape.ws" "follicle24Shape.sp";
connectAttr "headShape.o" "follicle24Shape.inm";
connectAttr "follicle24Shape.oha" "hairSystemShape1.ih[23]";
connectAttr "hairSystemShape1.oh[23]" "follicle24Shape.crp";
connectAttr "curve25Shape.ws" "follicle25Shape.sp";
connectAttr "headShape.o" "follicle25Shape.inm";
connectAttr "follicle25Shape.oha" "hairSystemShape1.ih[24]";
connectAttr "hairSystemShape1.oh[24]" "follicle25Shape.crp";
connectAttr "curve26Shape.ws" "follicle26Shape.sp";
connectAttr "headShape.o" "follicle26Shape.inm";
connectAttr "follicle26Shape.oha" "hairSystemShape1.ih[25]";
connectAttr "hairSystemShape1.oh[25]" "follicle26Shape.crp";
connectAttr "curve27Shape.ws" "follicle27Shape.sp";
connectAttr "headShape.o" "follicle27Shape.inm";
connectAttr "follicle27Shape.oha" "hairSystemShape1.ih[26]";
connectAttr "hairSystemShape1.oh[26]" "follicle27Shape.crp";
connectAttr "curve28Shape.ws" "follicle28Shape.sp";
connectAttr "headShape.o" "follicle28Shape.inm";
connectAttr "follicle28Shape.oha" "hairSystemShape1.ih[27]";
connectAttr "hairSystemShape1.oh[27]" "follicle28Shape.crp";
connectAttr "curve29Shape.ws" "follicle29Shape.sp";
connectAttr "headShape.o" "follicle29Shape.inm";
connectAttr "follicle29Shape.oha" "hairSystemShape1.ih[28]";
connectAttr "hairSystemShape1.oh[28]" "follicle29Shape.crp";
connectAttr "curve30Shape.ws" "follicle30Shape.sp";
connectAttr "headShape.o" "follicle30Shape.inm";
connectAttr "follicle30Shape.oha" "hairSystemShape1.ih[29]";
connectAttr "hairSystemShape1.oh[29]" "follicle30Shape.crp";
connectAttr "curve31Shape.ws" "follicle31Shape.sp";
connectAttr "headShape.o" "follicle31Shape.inm";
connectAttr "follicle31Shape.oha" "hairSystemShape1.ih[30]";
connectAttr "hairSystemShape1.oh[30]" "follicle31Shape.crp";
connectAttr "curve32Shape.ws" "follicle32Shape.sp";
connectAttr "headShape.o" "follicle32Shape.inm";
connectAttr "follicle32Shape.oha" "hairSystemShape1.ih[31]";
connectAttr "hairSystemShape1.oh[31]" "follicle32Shape.crp";
connectAttr "curve33Shape.ws" "follicle33Shape.sp";
connectAttr "headShape.o" "follicle33Shape.inm";
connectAttr "follicle33Shape.oha" "hairSystemShape1.ih[32]";
connectAttr "hairSystemShape1.oh[32]" "follicle33Shape.crp";
connectAttr "curve34Shape.ws" "follicle34Shape.sp";
connectAttr "headShape.o" "follicle34Shape.inm";
connectAttr "follicle34Shape.oha" "hairSystemShape1.ih[33]";
connectAttr "hairSystemShape1.oh[33]" "follicle34Shape.crp";
connectAttr "curve35Shape.ws" "follicle35Shape.sp";
connectAttr "headShape.o" "follicle35Shape.inm";
connectAttr "follicle35Shape.oha" "hairSystemShape1.ih[34]";
connectAttr "hairSystemShape1.oh[34]" "follicle35Shape.crp";
connectAttr "curve36Shape.ws" "follicle36Shape.sp";
connectAttr "headShape.o" "follicle36Shape.inm";
connectAttr "follicle36Shape.oha" "hairSystemShape1.ih[35]";
connectAttr "hairSystemShape1.oh[35]" "follicle36Shape.crp";
connectAttr "curve37Shape.ws" "follicle37Shape.sp";
connectAttr "headShape.o" "follicle37Shape.inm";
connectAttr "follicle37Shape.oha" "hairSystemShape1.ih[36]";
connectAttr "hairSystemShape1.oh[36]" "follicle37Shape.crp";
connectAttr "curve38Shape.ws" "follicle38Shape.sp";
connectAttr "headShape.o" "follicle38Shape.inm";
connectAttr "follicle38Shape.oha" "hairSystemShape1.ih[37]";
connectAttr "hairSystemShape1.oh[37]" "follicle38Shape.crp";
connectAttr "curve39Shape.ws" "follicle39Shape.sp";
connectAttr "headShape.o" "follicle39Shape.inm";
connectAttr "follicle39Shape.oha" "hairSystemShape1.ih[38]";
connectAttr "hairSystemShape1.oh[38]" "follicle39Shape.crp";
connectAttr "curve40Shape.ws" "follicle40Shape.sp";
connectAttr "headShape.o" "follicle40Shape.inm";
connectAttr "follicle40Shape.oha" "hairSystemShape1.ih[39]";
connectAttr "hairSystemShape1.oh[39]" "follicle40Shape.crp";
connectAttr "curve41Shape.ws" "follicle41Shape.sp";
connectAttr "headShape.o" "follicle41Shape.inm";
connectAttr "follicle41Shape.oha" "hairSystemShape1.ih[40]";
connectAttr "hairSystemShape1.oh[40]" "follicle41Shape.crp";
connectAttr "curve42Shape.ws" "follicle42Shape.sp";
connectAttr "headShape.o" "follicle42Shape.inm";
connectAttr "follicle42Shape.oha" "hairSystemShape1.ih[41]";
connectAttr "hairSystemShape1.oh[41]" "follicle42Shape.crp";
connectAttr "curve43Shape.ws" "follicle43Shape.sp";
connectAttr "headShape.o" "follicle43Shape.inm";
connectAttr "follicle43Shape.oha" "hairSystemShape1.ih[42]";
connectAttr "hairSystemShape1.oh[42]" "follicle43Shape.crp";
connectAttr "curve44Shape.ws" "follicle44Shape.sp";
connectAttr "headShape.o" "follicle44Shape.inm";
connectAttr "follicle44Shape.oha" "hairSystemShape1.ih[43]";
connectAttr "hairSystemShape1.oh[43]" "follicle44Shape.crp";
connectAttr "curve45Shape.ws" "follicle45Shape.sp";
connectAttr "headShape.o" "follicle45Shape.inm";
connectAttr "follicle45Shape.oha" "hairSystemShape1.ih[44]";
connectAttr "hairSystemShape1.oh[44]" "follicle45Shape.crp";
connectAttr "curve46Shape.ws" "follicle46Shape.sp";
connectAttr "headShape.o" "follicle46Shape.inm";
connectAttr "follicle46Shape.oha" "hairSystemShape1.ih[45]";
connectAttr "hairSystemShape1.oh[45]" "follicle46Shape.crp";
connectAttr "curve47Shape.ws" "follicle47Shape.sp";
connectAttr "headShape.o" "follicle47Shape.inm";
connectAttr "follicle47Shape.oha" "hairSystemShape1.ih[46]";
connectAttr "hairSystemShape1.oh[46]" "follicle47Shape.crp";
connectAttr "curve48Shape.ws" "follicle48Shape.sp";
connectAttr "headShape.o" "follicle48Shape.inm";
connectAttr "follicle48Shape.oha" "hairSystemShape1.ih[47]";
connectAttr "hairSystemShape1.oh[47]" "follicle48Shape.crp";
connectAttr "curve49Shape.ws" "follicle49Shape.sp";
connectAttr "headShape.o" "follicle49Shape.inm";
connectAttr "follicle49Shape.oha" "hairSystemShape1.ih[48]";
connectAttr "hairSystemShape1.oh[48]" "follicle49Shape.crp";
connectAttr "curve50Shape.ws" "follicle50Shape.sp";
connectAttr "headShape.o" "follicle50Shape.inm";
connectAttr "follicle50Shape.oha" "hairSystemShape1.ih[49]";
connectAttr "hairSystemShape1.oh[49]" "follicle50Shape.crp";
connectAttr "curve51Shape.ws" "follicle51Shape.sp";
connectAttr "headShape.o" "follicle51Shape.inm";
connectAttr "follicle51Shape.oha" "hairSystemShape1.ih[50]";
connectAttr "hairSystemShape1.oh[50]" "follicle51Shape.crp";
connectAttr "curve52Shape.ws" "follicle52Shape.sp";
connectAttr "headShape.o" "follicle52Shape.inm";
connectAttr "follicle52Shape.oha" "hairSystemShape1.ih[51]";
connectAttr "hairSystemShape1.oh[51]" "follicle52Shape.crp";
connectAttr "curve53Shape.ws" "follicle53Shape.sp";
connectAttr "headShape.o" "follicle53Shape.inm";
connectAttr "follicle53Shape.oha" "hairSystemShape1.ih[52]";
connectAttr "hairSystemShape1.oh[52]" "follicle53Shape.crp";
connectAttr "curve54Shape.ws" "follicle54Shape.sp";
connectAttr "headShape.o" "follicle54Shape.inm";
connectAttr "follicle54Shape.oha" "hairSystemShape1.ih[53]";
connectAttr "hairSystemShape1.oh[53]" "follicle54Shape.crp";
connectAttr "curve55Shape.ws" "follicle55Shape.sp";
connectAttr "headShape.o" "follicle55Shape.inm";
connectAttr "follicle55Shape.oha" "hairSystemShape1.ih[54]";
connectAttr "hairSystemShape1.oh[54]" "follicle55Shape.crp";
connectAttr "curve56Shape.ws" "follicle56Shape.sp";
connectAttr "headShape.o" "follicle56Shape.inm";
connectAttr "follicle56Shape.oha" "hairSystemShape1.ih[55]";
connectAttr "hairSystemShape1.oh[55]" "follicle56Shape.crp";
connectAttr "curve57Shape.ws" "follicle57Shape.sp";
connectAttr "headShape.o" "follicle57Shape.inm";
connectAttr "follicle57Shape.oha" "hairSystemShape1.ih[56]";
connectAttr "hairSystemShape1.oh[56]" "follicle57Shape.crp";
connectAttr "curve58Shape.ws" "follicle58Shape.sp";
connectAttr "headShape.o" "follicle58Shape.inm";
connectAttr "follicle58Shape.oha" "hairSystemShape1.ih[57]";
connectAttr "hairSystemShape1.oh[57]" "follicle58Shape.crp";
connectAttr "curve59Shape.ws" "follicle59Shape.sp";
connectAttr "headShape.o" "follicle59Shape.inm";
connectAttr "follicle59Shape.oha" "hairSystemShape1.ih[58]";
connectAttr "hairSystemShape1.oh[58]" "follicle59Shape.crp";
connectAttr "curve60Shape.ws" "follicle60Shape.sp";
connectAttr "headShape.o" "follicle60Shape.inm";
connectAttr "follicle60Shape.oha" "hairSystemShape1.ih[59]";
connectAttr "hairSystemShape1.oh[59]" "follicle60Shape.crp";
connectAttr "curve61Shape.ws" "follicle61Shape.sp";
connectAttr "headShape.o" "follicle61Shape.inm";
connectAttr "follicle61Shape.oha" "hairSystemShape1.ih[60]";
connectAttr "hairSystemShape1.oh[60]" "follicle61Shape.crp";
connectAttr "curve62Shape.ws" "follicle62Shape.sp";
connectAttr "headShape.o" "follicle62Shape.inm";
connectAttr "follicle62Shape.oha" "hairSystemShape1.ih[61]";
connectAttr "hairSystemShape1.oh[61]" "follicle62Shape.crp";
connectAttr "curve63Shape.ws" "follicle63Shape.sp";
connectAttr "headShape.o" "follicle63Shape.inm";
connectAttr "follicle63Shape.oha" "hairSystemShape1.ih[62]";
connectAttr "hairSystemShape1.oh[62]" "follicle63Shape.crp";
connectAttr "curve64Shape.ws" "follicle64Shape.sp";
connectAttr "headShape.o" "follicle64Shape.inm";
connectAttr "follicle64Shape.oha" "hairSystemShape1.ih[63]";
connectAttr "hairSystemShape1.oh[63]" "follicle64Shape.crp";
connectAttr "curve65Shape.ws" "follicle65Shape.sp";
connectAttr "headShape.o" "follicle65Shape.inm";
connectAttr "follicle65Shape.oha" "hairSystemShape1.ih[64]";
connectAttr "hairSystemShape1.oh[64]" "follicle65Shape.crp";
connectAttr "curve66Shape.ws" "follicle66Shape.sp";
connectAttr "headShape.o" "follicle66Shape.inm";
connectAttr "follicle66Shape.oha" "hairSystemShape1.ih[65]";
connectAttr "hairSystemShape1.oh[65]" "follicle66Shape.crp";
connectAttr "curve67Shape.ws" "follicle67Shape.sp";
connectAttr "headShape.o" "follicle67Shape.inm";
connectAttr "follicle67Shape.oha" "hairSystemShape1.ih[66]";
connectAttr "hairSystemShape1.oh[66]" "follicle67Shape.crp";
connectAttr "curve68Shape.ws" "follicle68Shape.sp";
connectAttr "headShape.o" "follicle68Shape.inm";
connectAttr "follicle68Shape.oha" "hairSystemShape1.ih[67]";
connectAttr "hairSystemShape1.oh[67]" "follicle68Shape.crp";
connectAttr "curve69Shape.ws" "follicle69Shape.sp";
connectAttr "headShape.o" "follicle69Shape.inm";
connectAttr "follicle69Shape.oha" "hairSystemShape1.ih[68]";
connectAttr "hairSystemShape1.oh[68]" "follicle69Shape.crp";
connectAttr "curve70Shape.ws" "follicle70Shape.sp";
connectAttr "headShape.o" "follicle70Shape.inm";
connectAttr "follicle70Shape.oha" "hairSystemShape1.ih[69]";
connectAttr "hairSystemShape1.oh[69]" "follicle70Shape.crp";
connectAttr "curve71Shape.ws" "follicle71Shape.sp";
connectAttr "headShape.o" "follicle71Shape.inm";
connectAttr "follicle71Shape.oha" "hairSystemShape1.ih[70]";
connectAttr "hairSystemShape1.oh[70]" "follicle71Shape.crp";
connectAttr "curve72Shape.ws" "follicle72Shape.sp";
connectAttr "headShape.o" "follicle72Shape.inm";
connectAttr "follicle72Shape.oha" "hairSystemShape1.ih[71]";
connectAttr "hairSystemShape1.oh[71]" "follicle72Shape.crp";
connectAttr "curve73Shape.ws" "follicle73Shape.sp";
connectAttr "headShape.o" "follicle73Shape.inm";
connectAttr "follicle73Shape.oha" "hairSystemShape1.ih[72]";
connectAttr "hairSystemShape1.oh[72]" "follicle73Shape.crp";
connectAttr "curve74Shape.ws" "follicle74Shape.sp";
connectAttr "headShape.o" "follicle74Shape.inm";
connectAttr "follicle74Shape.oha" "hairSystemShape1.ih[73]";
connectAttr "hairSystemShape1.oh[73]" "follicle74Shape.crp";
connectAttr "curve75Shape.ws" "follicle75Shape.sp";
connectAttr "headShape.o" "follicle75Shape.inm";
connectAttr "follicle75Shape.oha" "hairSystemShape1.ih[74]";
connectAttr "hairSystemShape1.oh[74]" "follicle75Shape.crp";
connectAttr "curve76Shape.ws" "follicle76Shape.sp";
connectAttr "headShape.o" "follicle76Shape.inm";
connectAttr "follicle76Shape.oha" "hairSystemShape1.ih[75]";
connectAttr "hairSystemShape1.oh[75]" "follicle76Shape.crp";
connectAttr "curve77Shape.ws" "follicle77Shape.sp";
connectAttr "headShape.o" "follicle77Shape.inm";
connectAttr "follicle77Shape.oha" "hairSystemShape1.ih[76]";
connectAttr "hairSystemShape1.oh[76]" "follicle77Shape.crp";
connectAttr "curve78Shape.ws" "follicle78Shape.sp";
connectAttr "headShape.o" "follicle78Shape.inm";
connectAttr "follicle78Shape.oha" "hairSystemShape1.ih[77]";
connectAttr "hairSystemShape1.oh[77]" "follicle78Shape.crp";
connectAttr "curve79Shape.ws" "follicle79Shape.sp";
connectAttr "headShape.o" "follicle79Shape.inm";
connectAttr "follicle79Shape.oha" "hairSystemShape1.ih[78]";
connectAttr "hairSystemShape1.oh[78]" "follicle79Shape.crp";
connectAttr "curve80Shape.ws" "follicle80Shape.sp";
connectAttr "headShape.o" "follicle80Shape.inm";
connectAttr "follicle80Shape.oha" "hairSystemShape1.ih[79]";
connectAttr "hairSystemShape1.oh[79]" "follicle80Shape.crp";
connectAttr "curve81Shape.ws" "follicle81Shape.sp";
connectAttr "headShape.o" "follicle81Shape.inm";
connectAttr "follicle81Shape.oha" "hairSystemShape1.ih[80]";
connectAttr "hairSystemShape1.oh[80]" "follicle81Shape.crp";
connectAttr "curve82Shape.ws" "follicle82Shape.sp";
connectAttr "headShape.o" "follicle82Shape.inm";
connectAttr "follicle82Shape.oha" "hairSystemShape1.ih[81]";
connectAttr "hairSystemShape1.oh[81]" "follicle82Shape.crp";
connectAttr "curve83Shape.ws" "follicle83Shape.sp";
connectAttr "headShape.o" "follicle83Shape.inm";
connectAttr "follicle83Shape.oha" "hairSystemShape1.ih[82]";
connectAttr "hairSystemShape1.oh[82]" "follicle83Shape.crp";
connectAttr "curve84Shape.ws" "follicle84Shape.sp";
connectAttr "headShape.o" "follicle84Shape.inm";
connectAttr "follicle84Shape.oha" "hairSystemShape1.ih[83]";
connectAttr "hairSystemShape1.oh[83]" "follicle84Shape.crp";
connectAttr "curve85Shape.ws" "follicle85Shape.sp";
connectAttr "headShape.o" "follicle85Shape.inm";
connectAttr "follicle85Shape.oha" "hairSystemShape1.ih[84]";
connectAttr "hairSystemShape1.oh[84]" "follicle85Shape.crp";
connectAttr "curve86Shape.ws" "follicle86Shape.sp";
connectAttr "headShape.o" "follicle86Shape.inm";
connectAttr "follicle86Shape.oha" "hairSystemShape1.ih[85]";
connectAttr "hairSystemShape1.oh[85]" "follicle86Shape.crp";
connectAttr "curve87Shape.ws" "follicle87Shape.sp";
connectAttr "headShape.o" "follicle87Shape.inm";
connectAttr "follicle87Shape.oha" "hairSystemShape1.ih[86]";
connectAttr "hairSystemShape1.oh[86]" "follicle87Shape.crp";
connectAttr "curve88Shape.ws" "follicle88Shape.sp";
connectAttr "headShape.o" "follicle88Shape.inm";
connectAttr "follicle88Shape.oha" "hairSystemShape1.ih[87]";
connectAttr "hairSystemShape1.oh[87]" "follicle88Shape.crp";
connectAttr "curve89Shape.ws" "follicle89Shape.sp";
connectAttr "headShape.o" "follicle89Shape.inm";
connectAttr "follicle89Shape.oha" "hairSystemShape1.ih[88]";
connectAttr "hairSystemShape1.oh[88]" "follicle89Shape.crp";
connectAttr "curve90Shape.ws" "follicle90Shape.sp";
connectAttr "headShape.o" "follicle90Shape.inm";
connectAttr "follicle90Shape.oha" "hairSystemShape1.ih[89]";
connectAttr "hairSystemShape1.oh[89]" "follicle90Shape.crp";
connectAttr "curve91Shape.ws" "follicle91Shape.sp";
connectAttr "headShape.o" "follicle91Shape.inm";
connectAttr "follicle91Shape.oha" "hairSystemShape1.ih[90]";
connectAttr "hairSystemShape1.oh[90]" "follicle91Shape.crp";
connectAttr "curve92Shape.ws" "follicle92Shape.sp";
connectAttr "headShape.o" "follicle92Shape.inm";
connectAttr "follicle92Shape.oha" "hairSystemShape1.ih[91]";
connectAttr "hairSystemShape1.oh[91]" "follicle92Shape.crp";
connectAttr "curve93Shape.ws" "follicle93Shape.sp";
connectAttr "headShape.o" "follicle93Shape.inm";
connectAttr "follicle93Shape.oha" "hairSystemShape1.ih[92]";
connectAttr "hairSystemShape1.oh[92]" "follicle93Shape.crp";
connectAttr "curve94Shape.ws" "follicle94Shape.sp";
connectAttr "headShape.o" "follicle94Shape.inm";
connectAttr "follicle94Shape.oha" "hairSystemShape1.ih[93]";
connectAttr "hairSystemShape1.oh[93]" "follicle94Shape.crp";
connectAttr "curve95Shape.ws" "follicle95Shape.sp";
connectAttr "headShape.o" "follicle95Shape.inm";
connectAttr "follicle95Shape.oha" "hairSystemShape1.ih[94]";
connectAttr "hairSystemShape1.oh[94]" "follicle95Shape.crp";
connectAttr "curve96Shape.ws" "follicle96Shape.sp";
connectAttr "headShape.o" "follicle96Shape.inm";
connectAttr "follicle96Shape.oha" "hairSystemShape1.ih[95]";
connectAttr "hairSystemShape1.oh[95]" "follicle96Shape.crp";
connectAttr "curve97Shape.ws" "follicle97Shape.sp";
connectAttr "headShape.o" "follicle97Shape.inm";
connectAttr "follicle97Shape.oha" "hairSystemShape1.ih[96]";
connectAttr "hairSystemShape1.oh[96]" "follicle97Shape.crp";
connectAttr "curve98Shape.ws" "follicle98Shape.sp";
connectAttr "headShape.o" "follicle98Shape.inm";
connectAttr "follicle98Shape.oha" "hairSystemShape1.ih[97]";
connectAttr "hairSystemShape1.oh[97]" "follicle98Shape.crp";
connectAttr "curve99Shape.ws" "follicle99Shape.sp";
connectAttr "headShape.o" "follicle99Shape.inm";
connectAttr "follicle99Shape.oha" "hairSystemShape1.ih[98]";
connectAttr "hairSystemShape1.oh[98]" "follicle99Shape.crp";
connectAttr "curve100Shape.ws" "follicle100Shape.sp";
connectAttr "headShape.o" "follicle100Shape.inm";
connectAttr "follicle100Shape.oha" "hairSystemShape1.ih[99]";
connectAttr "hairSystemShape1.oh[99]" "follicle100Shape.crp";
connectAttr "curve101Shape.ws" "follicle101Shape.sp";
connectAttr "headShape.o" "follicle101Shape.inm";
connectAttr "follicle101Shape.oha" "hairSystemShape1.ih[100]";
connectAttr "hairSystemShape1.oh[100]" "follicle101Shape.crp";
connectAttr "curve102Shape.ws" "follicle102Shape.sp";
connectAttr "headShape.o" "follicle102Shape.inm";
connectAttr "follicle102Shape.oha" "hairSystemShape1.ih[101]";
connectAttr "hairSystemShape1.oh[101]" "follicle102Shape.crp";
connectAttr "curve103Shape.ws" "follicle103Shape.sp";
connectAttr "headShape.o" "follicle103Shape.inm";
connectAttr "follicle103Shape.oha" "hairSystemShape1.ih[102]";
connectAttr "hairSystemShape1.oh[102]" "follicle103Shape.crp";
connectAttr "curve104Shape.ws" "follicle104Shape.sp";
connectAttr "headShape.o" "follicle104Shape.inm";
connectAttr "follicle104Shape.oha" "hairSystemShape1.ih[103]";
connectAttr "hairSystemShape1.oh[103]" "follicle104Shape.crp";
connectAttr "curve105Shape.ws" "follicle105Shape.sp";
connectAttr "headShape.o" "follicle105Shape.inm";
connectAttr "follicle105Shape.oha" "hairSystemShape1.ih[104]";
connectAttr "hairSystemShape1.oh[104]" "follicle105Shape.crp";
connectAttr "curve106Shape.ws" "follicle106Shape.sp";
connectAttr "headShape.o" "follicle106Shape.inm";
connectAttr "follicle106Shape.oha" "hairSystemShape1.ih[105]";
connectAttr "hairSystemShape1.oh[105]" "follicle106Shape.crp";
connectAttr "curve107Shape.ws" "follicle107Shape.sp";
connectAttr "headShape.o" "follicle107Shape.inm";
connectAttr "follicle107Shape.oha" "hairSystemShape1.ih[106]";
connectAttr "hairSystemShape1.oh[106]" "follicle107Shape.crp";
connectAttr "curve108Shape.ws" "follicle108Shape.sp";
connectAttr "headShape.o" "follicle108Shape.inm";
connectAttr "follicle108Shape.oha" "hairSystemShape1.ih[107]";
connectAttr "hairSystemShape1.oh[107]" "follicle108Shape.crp";
connectAttr "curve109Shape.ws" "follicle109Shape.sp";
connectAttr "headShape.o" "follicle109Shape.inm";
connectAttr "follicle109Shape.oha" "hairSystemShape1.ih[108]";
connectAttr "hairSystemShape1.oh[108]" "follicle109Shape.crp";
connectAttr "curve110Shape.ws" "follicle110Shape.sp";
connectAttr "headShape.o" "follicle110Shape.inm";
connectAttr "follicle110Shape.oha" "hairSystemShape1.ih[109]";
connectAttr "hairSystemShape1.oh[109]" "follicle110Shape.crp";
connectAttr "curve111Shape.ws" "follicle111Shape.sp";
connectAttr "headShape.o" "follicle111Shape.inm";
connectAttr "follicle111Shape.oha" "hairSystemShape1.ih[110]";
connectAttr "hairSystemShape1.oh[110]" "follicle111Shape.crp";
connectAttr "curve112Shape.ws" "follicle112Shape.sp";
connectAttr "headShape.o" "follicle112Shape.inm";
connectAttr "follicle112Shape.oha" "hairSystemShape1.ih[111]";
connectAttr "hairSystemShape1.oh[111]" "follicle112Shape.crp";
connectAttr "curve113Shape.ws" "follicle113Shape.sp";
connectAttr "headShape.o" "follicle113Shape.inm";
connectAttr "follicle113Shape.oha" "hairSystemShape1.ih[112]";
connectAttr "hairSystemShape1.oh[112]" "follicle113Shape.crp";
connectAttr "curve114Shape.ws" "follicle114Shape.sp";
connectAttr "headShape.o" "follicle114Shape.inm";
connectAttr "follicle114Shape.oha" "hairSystemShape1.ih[113]";
connectAttr "hairSystemShape1.oh[113]" "follicle114Shape.crp";
connectAttr "curve115Shape.ws" "follicle115Shape.sp";
connectAttr "headShape.o" "follicle115Shape.inm";
connectAttr "follicle115Shape.oha" "hairSystemShape1.ih[114]";
connectAttr "hairSystemShape1.oh[114]" "follicle115Shape.crp";
connectAttr "curve116Shape.ws" "follicle116Shape.sp";
connectAttr "headShape.o" "follicle116Shape.inm";
connectAttr "follicle116Shape.oha" "hairSystemShape1.ih[115]";
connectAttr "hairSystemShape1.oh[115]" "follicle116Shape.crp";
connectAttr "curve117Shape.ws" "follicle117Shape.sp";
connectAttr "headShape.o" "follicle117Shape.inm";
connectAttr "follicle117Shape.oha" "hairSystemShape1.ih[116]";
connectAttr "hairSystemShape1.oh[116]" "follicle117Shape.crp";
connectAttr "curve118Shape.ws" "follicle118Shape.sp";
connectAttr "headShape.o" "follicle118Shape.inm";
connectAttr "follicle118Shape.oha" "hairSystemShape1.ih[117]";
connectAttr "hairSystemShape1.oh[117]" "follicle118Shape.crp";
connectAttr "curve119Shape.ws" "follicle119Shape.sp";
connectAttr "headShape.o" "follicle119Shape.inm";
connectAttr "follicle119Shape.oha" "hairSystemShape1.ih[118]";
connectAttr "hairSystemShape1.oh[118]" "follicle119Shape.crp";
connectAttr "curve120Shape.ws" "follicle120Shape.sp";
connectAttr "headShape.o" "follicle120Shape.inm";
connectAttr "follicle120Shape.oha" "hairSystemShape1.ih[119]";
connectAttr "hairSystemShape1.oh[119]" "follicle120Shape.crp";
connectAttr "curve121Shape.ws" "follicle121Shape.sp";
connectAttr "headShape.o" "follicle121Shape.inm";
connectAttr "follicle121Shape.oha" "hairSystemShape1.ih[120]";
connectAttr "hairSystemShape1.oh[120]" "follicle121Shape.crp";
connectAttr "curve122Shape.ws" "follicle122Shape.sp";
connectAttr "headShape.o" "follicle122Shape.inm";
connectAttr "follicle122Shape.oha" "hairSystemShape1.ih[121]";
connectAttr "hairSystemShape1.oh[121]" "follicle122Shape.crp";
connectAttr "curve123Shape.ws" "follicle123Shape.sp";
connectAttr "headShape.o" "follicle123Shape.inm";
connectAttr "follicle123Shape.oha" "hairSystemShape1.ih[122]";
connectAttr "hairSystemShape1.oh[122]" "follicle123Shape.crp";
connectAttr "curve124Shape.ws" "follicle124Shape.sp";
connectAttr "headShape.o" "follicle124Shape.inm";
connectAttr "follicle124Shape.oha" "hairSystemShape1.ih[123]";
connectAttr "hairSystemShape1.oh[123]" "follicle124Shape.crp";
connectAttr "curve125Shape.ws" "follicle125Shape.sp";
connectAttr "headShape.o" "follicle125Shape.inm";
connectAttr "follicle125Shape.oha" "hairSystemShape1.ih[124]";
connectAttr "hairSystemShape1.oh[124]" "follicle125Shape.crp";
connectAttr "curve126Shape.ws" "follicle126Shape.sp";
connectAttr "headShape.o" "follicle126Shape.inm";
connectAttr "follicle126Shape.oha" "hairSystemShape1.ih[125]";
connectAttr "hairSystemShape1.oh[125]" "follicle126Shape.crp";
connectAttr "curve127Shape.ws" "follicle127Shape.sp";
connectAttr "headShape.o" "follicle127Shape.inm";
connectAttr "follicle127Shape.oha" "hairSystemShape1.ih[126]";
connectAttr "hairSystemShape1.oh[126]" "follicle127Shape.crp";
connectAttr "curve128Shape.ws" "follicle128Shape.sp";
connectAttr "headShape.o" "follicle128Shape.inm";
connectAttr "follicle128Shape.oha" "hairSystemShape1.ih[127]";
connectAttr "hairSystemShape1.oh[127]" "follicle128Shape.crp";
connectAttr "curve129Shape.ws" "follicle129Shape.sp";
connectAttr "headShape.o" "follicle129Shape.inm";
connectAttr "follicle129Shape.oha" "hairSystemShape1.ih[128]";
connectAttr "hairSystemShape1.oh[128]" "follicle129Shape.crp";
connectAttr "curve130Shape.ws" "follicle130Shape.sp";
connectAttr "headShape.o" "follicle130Shape.inm";
connectAttr "follicle130Shape.oha" "hairSystemShape1.ih[129]";
connectAttr "hairSystemShape1.oh[129]" "follicle130Shape.crp";
connectAttr "curve131Shape.ws" "follicle131Shape.sp";
connectAttr "headShape.o" "follicle131Shape.inm";
connectAttr "follicle131Shape.oha" "hairSystemShape1.ih[130]";
connectAttr "hairSystemShape1.oh[130]" "follicle131Shape.crp";
connectAttr "curve132Shape.ws" "follicle132Shape.sp";
connectAttr "headShape.o" "follicle132Shape.inm";
connectAttr "follicle132Shape.oha" "hairSystemShape1.ih[131]";
connectAttr "hairSystemShape1.oh[131]" "follicle132Shape.crp";
connectAttr "curve133Shape.ws" "follicle133Shape.sp";
connectAttr "headShape.o" "follicle133Shape.inm";
connectAttr "follicle133Shape.oha" "hairSystemShape1.ih[132]";
connectAttr "hairSystemShape1.oh[132]" "follicle133Shape.crp";
connectAttr "curve134Shape.ws" "follicle134Shape.sp";
connectAttr "headShape.o" "follicle134Shape.inm";
connectAttr "follicle134Shape.oha" "hairSystemShape1.ih[133]";
connectAttr "hairSystemShape1.oh[133]" "follicle134Shape.crp";
connectAttr "curve135Shape.ws" "follicle135Shape.sp";
connectAttr "headShape.o" "follicle135Shape.inm";
connectAttr "follicle135Shape.oha" "hairSystemShape1.ih[134]";
connectAttr "hairSystemShape1.oh[134]" "follicle135Shape.crp";
connectAttr "curve136Shape.ws" "follicle136Shape.sp";
connectAttr "headShape.o" "follicle136Shape.inm";
connectAttr "follicle136Shape.oha" "hairSystemShape1.ih[135]";
connectAttr "hairSystemShape1.oh[135]" "follicle136Shape.crp";
connectAttr "curve137Shape.ws" "follicle137Shape.sp";
connectAttr "headShape.o" "follicle137Shape.inm";
connectAttr "follicle137Shape.oha" "hairSystemShape1.ih[136]";
connectAttr "hairSystemShape1.oh[136]" "follicle137Shape.crp";
connectAttr "curve138Shape.ws" "follicle138Shape.sp";
connectAttr "headShape.o" "follicle138Shape.inm";
connectAttr "follicle138Shape.oha" "hairSystemShape1.ih[137]";
connectAttr "hairSystemShape1.oh[137]" "follicle138Shape.crp";
connectAttr "curve139Shape.ws" "follicle139Shape.sp";
connectAttr "headShape.o" "follicle139Shape.inm";
connectAttr "follicle139Shape.oha" "hairSystemShape1.ih[138]";
connectAttr "hairSystemShape1.oh[138]" "follicle139Shape.crp";
connectAttr "curve140Shape.ws" "follicle140Shape.sp";
connectAttr "headShape.o" "follicle140Shape.inm";
connectAttr "follicle140Shape.oha" "hairSystemShape1.ih[139]";
connectAttr "hairSystemShape1.oh[139]" "follicle140Shape.crp";
connectAttr "curve141Shape.ws" "follicle141Shape.sp";
connectAttr "headShape.o" "follicle141Shape.inm";
connectAttr "follicle141Shape.oha" "hairSystemShape1.ih[140]";
connectAttr "hairSystemShape1.oh[140]" "follicle141Shape.crp";
connectAttr "curve142Shape.ws" "follicle142Shape.sp";
connectAttr "headShape.o" "follicle142Shape.inm";
connectAttr "follicle142Shape.oha" "hairSystemShape1.ih[141]";
connectAttr "hairSystemShape1.oh[141]" "follicle142Shape.crp";
connectAttr "curve143Shape.ws" "follicle143Shape.sp";
connectAttr "headShape.o" "follicle143Shape.inm";
connectAttr "follicle143Shape.oha" "hairSystemShape1.ih[142]";
connectAttr "hairSystemShape1.oh[142]" "follicle143Shape.crp";
connectAttr "curve144Shape.ws" "follicle144Shape.sp";
connectAttr "headShape.o" "follicle144Shape.inm";
connectAttr "follicle144Shape.oha" "hairSystemShape1.ih[143]";
connectAttr "hairSystemShape1.oh[143]" "follicle144Shape.crp";
connectAttr "curve145Shape.ws" "follicle145Shape.sp";
connectAttr "headShape.o" "follicle145Shape.inm";
connectAttr "follicle145Shape.oha" "hairSystemShape1.ih[144]";
connectAttr "hairSystemShape1.oh[144]" "follicle145Shape.crp";
connectAttr "curve146Shape.ws" "follicle146Shape.sp";
connectAttr "headShape.o" "follicle146Shape.inm";
connectAttr "follicle146Shape.oha" "hairSystemShape1.ih[145]";
connectAttr "hairSystemShape1.oh[145]" "follicle146Shape.crp";
connectAttr "curve147Shape.ws" "follicle147Shape.sp";
connectAttr "headShape.o" "follicle147Shape.inm";
connectAttr "follicle147Shape.oha" "hairSystemShape1.ih[146]";
connectAttr "hairSystemShape1.oh[146]" "follicle147Shape.crp";
connectAttr "curve148Shape.ws" "follicle148Shape.sp";
connectAttr "headShape.o" "follicle148Shape.inm";
connectAttr "follicle148Shape.oha" "hairSystemShape1.ih[147]";
connectAttr "hairSystemShape1.oh[147]" "follicle148Shape.crp";
connectAttr "curve149Shape.ws" "follicle149Shape.sp";
connectAttr "headShape.o" "follicle149Shape.inm";
connectAttr "follicle149Shape.oha" "hairSystemShape1.ih[148]";
connectAttr "hairSystemShape1.oh[148]" "follicle149Shape.crp";
connectAttr "curve150Shape.ws" "follicle150Shape.sp";
connectAttr "headShape.o" "follicle150Shape.inm";
connectAttr "follicle150Shape.oha" "hairSystemShape1.ih[149]";
connectAttr "hairSystemShape1.oh[149]" "follicle150Shape.crp";
connectAttr "curve151Shape.ws" "follicle151Shape.sp";
connectAttr "headShape.o" "follicle151Shape.inm";
connectAttr "follicle151Shape.oha" "hairSystemShape1.ih[150]";
connectAttr "hairSystemShape1.oh[150]" "follicle151Shape.crp";
connectAttr "curve152Shape.ws" "follicle152Shape.sp";
connectAttr "headShape.o" "follicle152Shape.inm";
connectAttr "follicle152Shape.oha" "hairSystemShape1.ih[151]";
connectAttr "hairSystemShape1.oh[151]" "follicle152Shape.crp";
connectAttr "curve153Shape.ws" "follicle153Shape.sp";
connectAttr "headShape.o" "follicle153Shape.inm";
connectAttr "follicle153Shape.oha" "hairSystemShape1.ih[152]";
connectAttr "hairSystemShape1.oh[152]" "follicle153Shape.crp";
// End of maya_hair.ma
