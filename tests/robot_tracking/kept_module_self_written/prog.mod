MODULE Prog
  ! Module data whose write reads itself has no known size: its own bound is never assumed to
  ! prove itself (taken as its initial 1, the write would seem to give at most 3). It triples
  ! up to 1.5E38, and the height it is added to each cycle leaves the range of num.
  VAR num rise := 1;
  VAR robtarget pos;
  PROC main()
    MoveJ [[500, 0, 600], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]], v1000, fine, tool0;
    WHILE TRUE DO
      pos := CRobT();
      pos.trans.z := pos.trans.z + rise;
      MoveL pos, v100, fine, tool0;
      IF rise < 1E38 rise := rise * 3;
    ENDWHILE
  ENDPROC
ENDMODULE
