MODULE Pallet
  ! Issue 28: array sizes named by constants of a module not given. The value declared
  ! for each array fixes its size: nSlots is 25 and nRows 2, nCols 3 (from a 2 x 3
  ! value), not the 10 assumed when nothing tells the size (nSpare).
  PERS num heights{nSlots} := [5,10,15,20,25,30,35,40,45,50,55,60,65,70,75,80,85,90,95,
                               100,105,110,115,120,125];
  PERS num grid{nRows, nCols} := [[1, 2, 3], [4, 5, 6]];
  VAR num spare{nSpare};

  PROC main()
    FOR i FROM 1 TO nSlots DO
      TPWrite "slot" \Num:=heights{i};
    ENDFOR
    TPWrite "corner" \Num:=grid{nRows, nCols};
    spare{1} := grid{1, 1};
  ENDPROC
ENDMODULE
