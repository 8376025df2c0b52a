MODULE MainModule
  ! Tests: PoseVect maps a point through a frame: t + R*V.
  PROC main()
    VAR pose turned := [[100, 0, 0], [0, 0, 0, 1]];
    VAR pose shifted := [[1, 2, 3], [1, 0, 0, 0]];
    TPWrite "turned=" \Pos:=PoseVect(turned, [10, 20, 30]);
    TPWrite "shifted=" \Pos:=PoseVect(shifted, [10, 20, 30]);
  ENDPROC
ENDMODULE
