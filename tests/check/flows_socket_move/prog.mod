MODULE Recv
  VAR socketdev client;
  PERS tooldata gripper := [TRUE, [[0, 0, 150], [1, 0, 0, 0]], [1.5, [0, 0, 60], [1, 0, 0, 0], 0, 0, 0]];

  PROC main()
    VAR string message;
    VAR robtarget place := [[500, 0, 600], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
    VAR pos goal;
    SocketCreate client;
    SocketConnect client, "192.168.0.2", 1025 \Time:=5;
    SocketReceive client \Str:=message \Time:=5;
    IF StrToVal(message, goal) THEN
      place.trans := goal;
      MoveL place, v100, fine, gripper;
    ENDIF
  ERROR
    RETURN;
  ENDPROC
ENDMODULE
