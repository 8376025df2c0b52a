MODULE Cell
    ! Written for the test (issue 28): bRequest is set by T_RX and cleared here.
    PERS bool bRequest := FALSE;
    VAR socketdev client;
    VAR string reply := "";

    PROC main()
        WaitUntil bRequest;
        bRequest := FALSE;
        SocketCreate client;
        SocketConnect client, "192.168.125.5", 3000 \Time:=WAIT_MAX;
        SocketSend client \Str:="ready";
        SocketReceive client \Str:=reply;
        SocketClose client;
    ENDPROC
ENDMODULE
