MODULE SocketBracketList
    ! A PC sends a position as "[x,y,z]": the routine finds "[", then each "," and "]",
    ! and parses the three parts into a pos (the pattern of MARC-HT25's server).  The
    ! messages tried hold a list of three numbers, "[1,1,1]", and the shorter "[1,1]".
    VAR socketdev server;
    VAR socketdev client;
    VAR string received := "";
    VAR pos target := [0, 0, 0];
    VAR num done := 0;

    FUNC bool ReadPos(string text, INOUT pos value)
        VAR num first;
        VAR num last;
        first := StrFind(text, 1, "[") + 1;
        IF first > StrLen(text) RETURN FALSE;
        last := StrFind(text, first, ",");
        IF NOT StrToVal(StrPart(text, first, last - first), value.x) RETURN FALSE;
        first := last + 1;
        IF first > StrLen(text) RETURN FALSE;
        last := StrFind(text, first, ",");
        IF NOT StrToVal(StrPart(text, first, last - first), value.y) RETURN FALSE;
        first := last + 1;
        IF first > StrLen(text) RETURN FALSE;
        last := StrFind(text, first, "]");
        IF NOT StrToVal(StrPart(text, first, last - first), value.z) RETURN FALSE;
        RETURN TRUE;
    ENDFUNC

    PROC main()
        SocketCreate server;
        SocketBind server, "127.0.0.1", 5000;
        SocketListen server;
        SocketAccept server, client \Time:=WAIT_MAX;
        WHILE TRUE DO
            SocketReceive client \Str:=received \Time:=WAIT_MAX;
            IF ReadPos(received, target) THEN
                done := 1;
            ELSE
                done := -1;
            ENDIF
        ENDWHILE
    ENDPROC
ENDMODULE
