MODULE Prog
  ! The FOR's TO is routine data the routine writes (2E38 after its initial 1): the
  ! variable may be as big as num goes, and the height it is added to (3E38 higher after a
  ! cycle) leaves the range of num on the second cycle, wherever the robot started.
  PROC main()
    MoveJ [[500, 0, 600], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]], v1000, fine, tool0;
    WHILE TRUE DO
      Lift;
    ENDWHILE
  ENDPROC
  PROC Lift()
    VAR robtarget pos;
    VAR num rise := 1;
    rise := 2E38;
    pos := CRobT();
    FOR i FROM 0 TO rise STEP rise / 2 DO
      pos.trans.z := pos.trans.z + i;
      MoveL pos, v100, fine, tool0;
    ENDFOR
  ENDPROC
ENDMODULE
