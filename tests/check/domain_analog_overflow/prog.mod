MODULE prog
  ! An analog input scaled into a speed that only moves read: AInput may return the largest
  ! num, and 'AInput(ai_speed) * 10' then leaves the range of num (ERR_NUM_LIMIT).  Its value
  ! reaches an operation that can fail, so it gets no default domain.  Before, the input
  ! took one value (0) and no_runtime_error came out HOLDS; with --input-domain
  ! AI_SPEED=0,3E38 it is VIOLATED.
  VAR signalai ai_speed;
  VAR speeddata speed := [100, 500, 5000, 1000];
  PROC main()
    AliasIO "AI_SPEED", ai_speed;
    speed.v_tcp := AInput(ai_speed) * 10;
    MoveL home, speed, z10, tool0;
  ENDPROC
  CONST robtarget home := [[500, 0, 600], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
ENDMODULE
