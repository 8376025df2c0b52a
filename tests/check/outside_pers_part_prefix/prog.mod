MODULE OutsidePartPrefix
    ! Issue 33: a PC puts a command word and its parameters into the PERS command
    ! ("workoffset,0.01,-0.28") and this task waits for the word alone, compared through
    ! StrPart (Hanoi TASK1's rWorkFlow). No loaded write ends WaitUntil command <> "", so
    ! a PC writes command (awaited from outside); its domain holds the text that makes
    ! each part equal, so the waits may end and the code after them runs (without it the
    ! domain was "" and one other text, neither StrPart wait ever ended, and the code
    ! after the first was "never reached under any input"). Each read in a wait chooses
    ! afresh, so the PC may have emptied command again: StrPart of "" raises
    ! ERR_ARGVALERR (no_runtime_error VIOLATED, as before).
    PERS string command := "";
    VAR num offsets := 0;
    VAR num guided := 0;

    PROC main()
        command := "";
        WaitUntil command <> "";
        WaitUntil StrPart(command, 1, 10) = "workoffset";
        offsets := offsets + 1;
        command := "";
        WaitUntil command <> "";
        WaitUntil StrPart(command, 3, 5) = "guide";
        guided := 1;
    ENDPROC
ENDMODULE
