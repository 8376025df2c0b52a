MODULE Flows
  VAR socketdev client;
  VAR iodev channel;
  VAR signalai ai_force;
  VAR signalgo go_recipe;
  PERS tooldata gripper := [TRUE, [[0, 0, 150], [1, 0, 0, 0]], [1.5, [0, 0, 60], [1, 0, 0, 0], 0, 0, 0]];
  CONST robtarget home := [[500, 0, 600], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];

  PROC main()
    VAR string routine_name;
    VAR string file_name;
    VAR num recipe;
    VAR num depth;
    VAR speeddata speed := [100, 500, 5000, 1000];
    SocketReceive client \Str:=routine_name \Time:=5;
    CallByVar routine_name, 1;  ! expect: RMC820
    %routine_name%;  ! expect: RMC820
    file_name := ReadStr(channel \Time:=5);
    Open file_name, channel \Read;  ! expect: RMC820
    TPReadNum recipe, "Recipe?";
    SetGO go_recipe, recipe;  ! expect: RMC820
    IF recipe >= 0 AND recipe <= 15 THEN
      SetGO go_recipe, recipe;
    ENDIF
    speed.v_tcp := AInput(ai_force) * 10;
    MoveL home, speed, fine, gripper;  ! expect: RMC820
    depth := ai_force;
    Lower depth;
  ERROR
    RETURN;
  ENDPROC

  PROC Lower(num amount)
    MoveL Offs(home, 0, 0, -amount), v100, fine, gripper;  ! expect: RMC820
  ENDPROC
ENDMODULE
