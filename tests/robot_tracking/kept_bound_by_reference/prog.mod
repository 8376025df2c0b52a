MODULE Prog
  ! Routine data written only as a by-reference argument (Add's INOUT Name): its initial 0
  ! is no bound, the height it is added to leaves the range of num on the second cycle.
  PROC main()
    MoveJ [[500, 0, 600], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]], v1000, fine, tool0;
    WHILE TRUE DO
      Lift;
    ENDWHILE
  ENDPROC
  PROC Lift()
    VAR robtarget pos;
    VAR num rise;
    Add rise, 3E38;
    pos := CRobT();
    pos.trans.z := pos.trans.z + rise;
    MoveL pos, v100, fine, tool0;
  ENDPROC
ENDMODULE
