MODULE OutsidePartPrefix
    ! Issue 33: a PC puts a command word and its parameters into the PERS command
    ! ("workoffset,0.01,-0.28") and this task waits for the word alone, compared through
    ! StrPart (Hanoi TASK1's rWorkFlow). No loaded write ends WaitUntil command <> "", so
    ! a PC writes command (awaited from outside); its domain holds the text that makes
    ! each part equal, so the waits may end and the code after them runs (without it the
    ! domain was "" and one other text, neither StrPart wait ever ended, and the code
    ! after the first was "never reached under any input"). no_runtime_error is VIOLATED
    ! for a real reason: a command shorter than 10 characters that ends the first wait
    ! ("  guide", kept: a wait's read offers the stored value first, so the counterexample
    ! shows it rather than a command the PC emptied again) makes StrPart raise
    ! ERR_ARGVALERR in the second.
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
