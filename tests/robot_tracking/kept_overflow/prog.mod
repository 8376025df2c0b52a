MODULE Prog
  ! Each cycle doubles the height the robot is at: after about 120 cycles it leaves the range
  ! of num (ERR_NUM_LIMIT), wherever the robot started.
  VAR robtarget pos;
  PROC main()
    MoveJ [[500, 0, 600], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]], v1000, fine, tool0;
    WHILE TRUE DO
      pos := CRobT();
      pos.trans.z := pos.trans.z * 2;
      MoveL pos, v100, fine, tool0;
    ENDWHILE
  ENDPROC
ENDMODULE
