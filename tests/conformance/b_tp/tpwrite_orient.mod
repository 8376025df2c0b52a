MODULE MainModule
  ! Tests: TPWrite \Orient appends the quaternion as [q1,q2,q3,q4] without spaces.
  PROC main()
    VAR orient o := [0.5, 0.5, 0.5, 0.5];
    TPWrite "id=" \Orient:=[1, 0, 0, 0];
    TPWrite "o=" \Orient:=o;
  ENDPROC
ENDMODULE
