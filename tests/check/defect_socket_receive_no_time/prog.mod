MODULE DefectReceiveNoTime
    ! Issue 19, a true defect that must stay found: a server receives without \Time and
    ! without an ERROR handler, so a client that sends nothing for 60 s stops the task
    ! with ERR_SOCK_TIMEOUT.
    VAR socketdev server;
    VAR socketdev client;
    VAR string request := "";

    PROC main()
        SocketCreate server;
        SocketBind server, "127.0.0.1", 1025;
        SocketListen server;
        SocketAccept server, client \Time:=WAIT_MAX;
        WHILE TRUE DO
            SocketReceive client \Str:=request;
            SocketSend client \Str:="ack";
        ENDWHILE
    ENDPROC
ENDMODULE
