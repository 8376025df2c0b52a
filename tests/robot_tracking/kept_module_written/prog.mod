MODULE Prog
  ! Module data another routine writes (3E38 after its initial 1) has no known size: the
  ! height it is added to leaves the range of num on the second cycle.
  VAR num rise := 1;
  VAR robtarget pos;
  PROC main()
    MoveJ [[500, 0, 600], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]], v1000, fine, tool0;
    Setup;
    WHILE TRUE DO
      pos := CRobT();
      pos.trans.z := pos.trans.z + rise;
      MoveL pos, v100, fine, tool0;
    ENDWHILE
  ENDPROC
  PROC Setup()
    rise := 3E38;
  ENDPROC
ENDMODULE
