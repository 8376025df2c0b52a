MODULE Prog
  ! Module data written by name (SetDataVal "rise"): no assignment names it, but it holds
  ! 3E38 after its initial 1, and the height it shifts the robot by each cycle leaves the
  ! range of num on the second cycle.
  CONST num big := 3E38;
  VAR num rise := 1;
  PROC main()
    MoveJ [[500, 0, 600], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]], v1000, fine, tool0;
    SetDataVal "rise", big;
    WHILE TRUE DO
      MoveL Offs(CRobT(), 0, 0, rise), v100, fine, tool0;
    ENDWHILE
  ENDPROC
ENDMODULE
