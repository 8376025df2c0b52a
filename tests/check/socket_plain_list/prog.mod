MODULE SocketPlainList
    ! A PC sends a target as "x,y,z", with no brackets and no command word: the server
    ! cuts it at each "," and parses the three parts (the pattern of a held-out server
    ! that moves the robot by the offsets received). The messages tried hold a list of
    ! three numbers, "1,1,1", a shorter one and one whose last part does not parse; before,
    ! only "," and "?" were tried and the move was "never reached".
    VAR socketdev server;
    VAR socketdev client;
    VAR string data := "";
    VAR pos offset := [0, 0, 0];
    VAR num parsed := 0;

    PROC Split()
        VAR num first := 1;
        VAR num last;
        parsed := 0;
        last := StrFind(data, first, ",");
        IF last > StrLen(data) RETURN;
        IF NOT StrToVal(StrPart(data, first, last - first), offset.x) RETURN;
        parsed := 1;
        first := last + 1;
        last := StrFind(data, first, ",");
        IF last > StrLen(data) RETURN;
        IF NOT StrToVal(StrPart(data, first, last - first), offset.y) RETURN;
        parsed := 2;
        first := last + 1;
        IF NOT StrToVal(StrPart(data, first, StrLen(data) - last), offset.z) RETURN;
        parsed := 3;
    ENDPROC

    PROC main()
        SocketCreate server;
        SocketBind server, "127.0.0.1", 1025;
        SocketListen server;
        SocketAccept server, client \Time:=WAIT_MAX;
        WHILE TRUE DO
            SocketReceive client \Str:=data \Time:=WAIT_MAX;
            Split;
        ENDWHILE
    ENDPROC
ENDMODULE
