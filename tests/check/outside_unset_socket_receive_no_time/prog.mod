MODULE UnsetReceiveNoTime
    ! Issue 28, a true defect that must stay found: started by a flag a PC sets, the server
    ! receives without \Time and without an ERROR handler, so a client that sends nothing
    ! for 60 s stops the task with ERR_SOCK_TIMEOUT. The flag is declared without a value.
    PERS bool bServerOn;
    VAR socketdev server;
    VAR socketdev client;
    VAR string request := "";

    PROC main()
        WaitUntil bServerOn;
        SocketCreate server;
        SocketBind server, "127.0.0.1", 1025;
        SocketListen server;
        SocketAccept server, client \Time:=WAIT_MAX;
        WHILE bServerOn DO
            SocketReceive client \Str:=request;
            SocketSend client \Str:="ack";
        ENDWHILE
        SocketClose client;
        SocketClose server;
    ENDPROC
ENDMODULE
