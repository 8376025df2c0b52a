MODULE Partner
  PERS string shared := "";
  PERS num speed := 100;
  VAR socketdev client;
  PROC main()
    shared := "go";                                ! SHARED
    speed := 50;                                   ! SHARED
    SocketCreate client;                           ! LOCAL
    SocketConnect client, "127.0.0.1", 1025 \Time:=5;  ! LOCAL
  ENDPROC
ENDMODULE
